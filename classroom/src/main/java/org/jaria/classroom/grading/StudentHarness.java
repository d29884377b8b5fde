package org.jaria.classroom.grading;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.classroom.link.Frames;
import org.jaria.classroom.link.StudentContext;
import org.jaria.classroom.link.StudentSide;
import org.jaria.clock.Clock;
import org.jaria.clock.VirtualClock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.PipeConnection;
import org.jaria.robot.ArRobot;

/**
 * The student's side of the robot link: an ArRobot on a virtual clock that only the grader's frames
 * move, the student's object hooked to it, and the program thread. Each tick it delivers the
 * simulator's bytes, moves the clock to the grader's time, runs the robot's cycle as {@code
 * SimulatedRobot} does (once per SIP, or after two cycle times without one) and, while a program
 * runs, waits until the program waits on the clock again (or ends, or has computed for {@link
 * Programs#STUCK_AFTER} of real time without waiting: stuck). Then it answers with what the robot
 * wrote.
 */
final class StudentHarness {

  private final Assignment assignment;
  private final ClassLoader loader;
  private final List<String> classNames;
  private final DataInputStream in;
  private final DataOutputStream out;
  private final ReentrantLock writeLock = new ReentrantLock();
  private final VirtualClock clock = new VirtualClock();
  private final List<PipeConnection> ends = new ArrayList<>();
  private final Map<String, PipeConnection> devices = new LinkedHashMap<>();
  private final byte[] buf = new byte[1 << 16];
  private ArRobot robot;
  private StudentSide side;
  private Class<?> solution;
  private final StudentProgram program = new StudentProgram(clock);
  private long lastCycleNanos;
  private volatile boolean ended;

  /**
   * A harness for {@code assignment} over the grader's streams, with the student's classes (named
   * {@code classNames}) loaded by {@code loader}.
   */
  public StudentHarness(
      Assignment assignment,
      ClassLoader loader,
      List<String> classNames,
      DataInputStream in,
      DataOutputStream out) {
    this.assignment = assignment;
    this.loader = loader;
    this.classNames = List.copyOf(classNames);
    this.in = in;
    this.out = out;
  }

  /**
   * What to do when the program runs out of memory or threads (the student's JVM ends at once, so
   * the grader names it; in a shared JVM nothing is done).
   */
  public void onResourceError(java.util.function.Consumer<OutOfMemoryError> action) {
    program.onResourceError(action);
  }

  /** Whether the grader ended the link normally (END answered). */
  public boolean ended() {
    return ended;
  }

  /**
   * Tells the grader this JVM is shutting down although the grader did not end the link (a shutdown
   * hook calls it: the student's code called System.exit). Gives up after a second.
   */
  public void announceExit() {
    if (ended) {
      return;
    }
    try {
      if (writeLock.tryLock(1, TimeUnit.SECONDS)) {
        try {
          out.writeByte(Frames.EXITING);
          out.flush();
        } finally {
          writeLock.unlock();
        }
      }
    } catch (IOException | InterruptedException e) {
      // the grader is gone or we are being stopped: nothing to tell
    }
  }

  /**
   * Answers the grader's frames until END.
   *
   * @throws IOException if the grader's stream breaks or sends something that is not a frame
   */
  public void serve() throws IOException {
    while (true) {
      int type = in.read();
      if (type < 0) {
        throw new IOException("the grader closed the link");
      }
      switch (type) {
        case Frames.HELLO -> hello();
        case Frames.TICK -> tick();
        case Frames.SET_UP -> reply(setUp());
        case Frames.CALL -> reply(call(Frames.readString(in)));
        case Frames.PROGRAM -> {
          program.start(robot);
          state();
        }
        case Frames.STOP -> {
          program.stop();
          reply("");
        }
        case Frames.END -> {
          program.stop();
          ended = true;
          writeLock.lock();
          try {
            out.writeByte(Frames.BYE);
            out.flush();
          } finally {
            writeLock.unlock();
          }
          return;
        }
        default -> throw new IOException("not a frame: " + type);
      }
    }
  }

  private void hello() throws IOException {
    String name = Frames.readString(in);
    int n = in.readUnsignedByte();
    if (n < 1 || n > Frames.MAX_CHANNELS) {
      throw new IOException("bad frame: " + n + " channels");
    }
    List<String> names = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      names.add(Frames.readString(in));
    }
    for (String channel : names) {
      PipeConnection.Pair pair = PipeConnection.pair(clock, channel);
      pair.a().open();
      pair.b().open();
      ends.add(pair.b());
      devices.put(channel, pair.a());
    }
    robot = new ArRobot(name, clock, true);
    robot.setDeviceConnection(devices.get(names.get(0)));
    robot.asyncConnect();
    reply("");
  }

  private void tick() throws IOException {
    long now = in.readLong();
    for (PipeConnection end : ends) {
      byte[] b = Frames.readBytes(in);
      if (b.length > 0) {
        end.write(b, 0, b.length);
      }
    }
    clock.advanceTo(now);
    cycle();
    if (program.state() == StudentProgram.RUNNING) {
      program.await();
    }
    state();
  }

  /** The robot's cycle, driven as SimulatedRobot drives it. */
  private void cycle() {
    if (robot == null) {
      return;
    }
    long now = clock.nanoTime();
    long fallback = TimeUnit.MILLISECONDS.toNanos(2L * robot.getCycleTime());
    if (robot.isConnecting() || robot.pollForSip() || now - lastCycleNanos >= fallback) {
      lastCycleNanos = now;
      robot.loopOnce();
    }
  }

  private String setUp() {
    try {
      solution = SolutionFinder.find(assignment, loader, classNames);
    } catch (Solutions.SolutionException e) {
      return Solutions.setUpAnswer("setup.found.name", e.key(), e.args());
    }
    try {
      side = assignment.studentSide();
      side.setUp(context());
      return "";
    } catch (Solutions.SolutionException e) {
      return Solutions.setUpAnswer("setup.created.name", e.key(), e.args());
    } catch (RuntimeException | LinkageError e) {
      return Solutions.setUpAnswer(
          "setup.created.name", "setup.failed", List.of(Solutions.describe(e)));
    }
  }

  private String call(String name) {
    return side == null ? "" : side.call(name);
  }

  private StudentContext context() {
    return new StudentContext() {
      @Override
      public ArRobot robot() {
        return robot;
      }

      @Override
      public Clock clock() {
        return clock;
      }

      @Override
      public ArDeviceConnection channel(String name) {
        PipeConnection c = devices.get(name);
        if (c == null) {
          throw new IllegalArgumentException("no channel '" + name + "': " + devices.keySet());
        }
        return c;
      }

      @Override
      public Class<?> solution() {
        return solution;
      }

      @Override
      public void setProgram(Programs.Body body) {
        program.set(body);
      }
    };
  }

  private void state() throws IOException {
    int flags = 0;
    String msg = program.message();
    if (robot != null) {
      flags = (robot.isConnecting() ? 1 : 0) | (robot.isConnected() ? 2 : 0);
      if (!robot.isConnecting() && !robot.isConnected()) {
        msg = String.valueOf(robot.getConnectFailure());
      }
    }
    writeLock.lock();
    try {
      out.writeByte(Frames.STATE);
      out.writeByte(program.state());
      out.writeByte(flags);
      Frames.writeString(out, msg);
      for (PipeConnection end : ends) {
        int n = 0;
        while (n < buf.length) {
          int r = end.read(buf, n, buf.length - n, 0);
          if (r <= 0) {
            break;
          }
          n += r;
        }
        Frames.writeBytes(out, buf, n);
      }
      out.flush();
    } finally {
      writeLock.unlock();
    }
  }

  private void reply(String s) throws IOException {
    writeLock.lock();
    try {
      out.writeByte(Frames.REPLY);
      Frames.writeString(out, s);
      out.flush();
    } finally {
      writeLock.unlock();
    }
  }
}
