package org.jaria.classroom.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot.ProgramResult;

/**
 * The grader's side of a student's robot: the simulated robot's connection and any other device
 * channels (an ACTS server's pipe) carried over {@link StudentStreams} to the student's JVM, in
 * lockstep. After every world step the bytes the simulator wrote and the new virtual time go to the
 * student's side, which runs its ArRobot's cycle and lets the program run until it waits on the
 * clock again; the bytes its robot wrote come back and are delivered before the next step. So the
 * student's program sees exactly what an in-process {@code SimulatedRobot} would, while it can
 * reach nothing of the grader: the world, the ground truth and the grade stay here.
 *
 * <p>Everything the student's side reports (whether the program ended, what its actions threw) is a
 * claim by the student's process; the checks worth most points are made on the world's ground
 * truth. The robot's channel carries to the simulator only what a real Pioneer accepts ({@link
 * RobotCommands}): simulator control such as MobileSim's SIM_SET_POSE never reaches the world, and
 * every packet dropped is counted in the streams' {@link LinkAudit}. After every step the robot's
 * true pose is compared with the one before; a jump no robot can drive is recorded there too, and
 * costs the student the whole grade.
 *
 * <p>Any failure of the link (the process ended, was killed, sent garbage) throws {@link LinkLost}
 * out of the world's step, and so out of the assignment's grading.
 */
public final class StudentLink implements AutoCloseable {

  /**
   * How much faster than its model's top speeds (the most its firmware allows) a robot's true pose
   * may move before it counts as a jump.
   */
  static final double SPEED_MARGIN = 1.2;

  /** What a step may add to that (rounding, a push at a collision), mm and degrees. */
  static final double SLACK_MM = 20;

  static final double SLACK_DEG = 5;

  private final double maxMmPerS;
  private final double maxDegPerS;

  private final SimWorld world;
  private final SimRobot robot;
  private final LinkAudit audit;
  private final RobotCommandFilter robotFilter;
  private final long t0;
  private ArPose lastPose;
  private long lastPoseNanos;
  private final DataInputStream in;
  private final DataOutputStream out;
  private final List<ArDeviceConnection> channels;
  private final Runnable bridge = this::tick;
  private final byte[] buf = new byte[1 << 16];
  private ProgramResult programResult;
  private boolean programRunning;
  private String message = "";
  private int robotFlags;
  private boolean closed;

  private StudentLink(
      SimWorld world, SimRobot robot, StudentStreams s, List<ArDeviceConnection> channels) {
    this.world = world;
    this.robot = robot;
    this.in = s.in();
    this.out = s.out();
    this.audit = s.audit();
    this.robotFilter = new RobotCommandFilter(s.audit(), robot.getName());
    this.channels = channels;
    this.t0 = world.getClock().nanoTime();
    this.lastPose = robot.getTruePose();
    this.lastPoseNanos = t0;
    this.maxMmPerS = SPEED_MARGIN * robot.getModel().getTransVelTop();
    this.maxDegPerS = SPEED_MARGIN * robot.getModel().getRotVelTop();
  }

  /**
   * Connects the student's robot to {@code robot} over {@code streams}, with {@code extra} device
   * channels (by name, the grader's end of each), and runs the world until the robot's handshake is
   * done.
   *
   * @throws LinkLost if the student's side does not answer
   * @throws IllegalStateException if the robot does not connect within 30 s of virtual time
   */
  public static StudentLink connect(
      SimWorld world,
      SimRobot robot,
      StudentStreams streams,
      Map<String, ? extends ArDeviceConnection> extra) {
    Map<String, ArDeviceConnection> all = new LinkedHashMap<>();
    all.put("robot", robot.connectInMemory());
    all.putAll(extra);
    StudentLink link = new StudentLink(world, robot, streams, new ArrayList<>(all.values()));
    link.hello(robot.getName(), new ArrayList<>(all.keySet()));
    world.addStepListener(link.bridge);
    if (!link.runUntil(() -> (link.robotFlags & 1) == 0, Duration.ofSeconds(30))
        || (link.robotFlags & 2) == 0) {
      link.close();
      throw new IllegalStateException(
          "the student's robot did not connect to the simulator: " + link.message);
    }
    return link;
  }

  private void hello(String robotName, List<String> names) {
    try {
      out.writeByte(Frames.HELLO);
      Frames.writeString(out, robotName);
      out.writeByte(names.size());
      for (String n : names) {
        Frames.writeString(out, n);
      }
      out.flush();
      reply();
      robotFlags = 1; // connecting, until the first tick says otherwise
    } catch (IOException e) {
      throw lost(e);
    }
  }

  /**
   * Makes the student's object and hooks it to the robot (their constructor runs now).
   *
   * @return empty, or the failed check's name and message, tab-separated
   */
  public Optional<String> setUp() {
    try {
      out.writeByte(Frames.SET_UP);
      out.flush();
      String r = reply();
      return r.isEmpty() ? Optional.empty() : Optional.of(r);
    } catch (IOException e) {
      throw lost(e);
    }
  }

  /** Asks the assignment's student side {@code name} (a fact, or a step it takes). */
  public String call(String name) {
    try {
      out.writeByte(Frames.CALL);
      Frames.writeString(out, name);
      out.flush();
      return reply();
    } catch (IOException e) {
      throw lost(e);
    }
  }

  /**
   * Moves the robot to {@code p} from the grader's side (a "kidnapped robot" assignment, say),
   * without the move counting as a jump of its path.
   */
  public void moveRobot(ArPose p) {
    robot.setTruePose(p);
    lastPose = robot.getTruePose();
  }

  /** What the link dropped so far and whether the robot's path jumped. */
  public LinkAudit audit() {
    return audit;
  }

  /** Runs {@code ms} of virtual time. */
  public void runMillis(long ms) {
    world.advanceMillis(ms);
  }

  /**
   * Runs until {@code done} is true (checked after every tick) or {@code max} of virtual time has
   * passed.
   *
   * @return whether {@code done} became true
   */
  public boolean runUntil(BooleanSupplier done, Duration max) {
    long end = world.getClock().nanoTime() + max.toNanos();
    while (!done.getAsBoolean()) {
      if (world.getClock().nanoTime() >= end) {
        return false;
      }
      world.step();
    }
    return true;
  }

  /**
   * Runs the student's sequential program for at most {@code max} of virtual time: the world steps
   * only while the program waits on the robot's clock, as {@code SimulatedRobot.runProgram} does in
   * one JVM.
   */
  public ProgramResult runProgram(Duration max) {
    long end = world.getClock().nanoTime() + max.toNanos();
    programResult = null;
    programRunning = true;
    try {
      out.writeByte(Frames.PROGRAM);
      out.flush();
      state();
    } catch (IOException e) {
      throw lost(e);
    }
    while (programResult == null) {
      if (world.getClock().nanoTime() >= end) {
        try {
          out.writeByte(Frames.STOP);
          out.flush();
          reply();
        } catch (IOException e) {
          throw lost(e);
        }
        programRunning = false;
        return ProgramResult.TIMED_OUT;
      }
      world.step();
    }
    programRunning = false;
    return programResult;
  }

  /** What the program threw, as the student's side described it, when it ended FAILED. */
  public String programFailure() {
    return message;
  }

  private void tick() {
    watchPose();
    try {
      out.writeByte(Frames.TICK);
      out.writeLong(world.getClock().nanoTime());
      for (ArDeviceConnection c : channels) {
        int n = drain(c);
        Frames.writeBytes(out, buf, n);
      }
      out.flush();
      state();
    } catch (IOException e) {
      throw lost(e);
    }
  }

  /** Records a jump of the robot's true pose over the step just taken. */
  private void watchPose() {
    long now = world.getClock().nanoTime();
    ArPose p = robot.getTruePose();
    double dt = Math.max(0, (now - lastPoseNanos) / 1e9);
    double mm = Math.hypot(p.x() - lastPose.x(), p.y() - lastPose.y());
    double deg = Math.abs(ArMath.subAngle(p.th(), lastPose.th()));
    if (mm > maxMmPerS * dt + SLACK_MM || deg > maxDegPerS * dt + SLACK_DEG) {
      audit.jump(
          new LinkAudit.Jump((now - t0) / 1e9, lastPose.x(), lastPose.y(), p.x(), p.y(), mm, deg));
    }
    lastPose = p;
    lastPoseNanos = now;
  }

  /** Reads everything the simulator side wrote on {@code c} since the last tick into buf. */
  private int drain(ArDeviceConnection c) throws IOException {
    int n = 0;
    while (n < buf.length) {
      int r = c.read(buf, n, buf.length - n, 0);
      if (r <= 0) {
        break;
      }
      n += r;
    }
    return n;
  }

  private void state() throws IOException {
    expect(Frames.STATE);
    int program = in.readUnsignedByte();
    robotFlags = in.readUnsignedByte();
    message = Frames.readString(in);
    for (int i = 0; i < channels.size(); i++) {
      ArDeviceConnection c = channels.get(i);
      byte[] b = Frames.readBytes(in);
      if (i == 0) {
        robotFilter.feed(b, b.length, world.getClock().nanoTime(), c);
      } else if (b.length > 0 && c.getStatus() == ArDeviceConnection.Status.OPEN) {
        c.write(b, 0, b.length);
      }
    }
    if (programRunning && programResult == null) {
      programResult =
          switch (program) {
            case 2 -> ProgramResult.FINISHED;
            case 3 -> ProgramResult.FAILED;
            case 4 -> ProgramResult.STUCK;
            default -> null;
          };
    }
  }

  private String reply() throws IOException {
    expect(Frames.REPLY);
    return Frames.readString(in);
  }

  private void expect(int type) throws IOException {
    int t = in.read();
    if (t < 0) {
      throw new EOFException("the student's process ended");
    }
    if (t == Frames.EXITING) {
      throw new LinkLost("the student's program called System.exit", true, null);
    }
    if (t != type) {
      throw new IOException(
          "the student's process sent frame '"
              + (char) t
              + "' where '"
              + (char) type
              + "' was due");
    }
  }

  private static LinkLost lost(IOException e) {
    return new LinkLost("robot link lost: " + e.getMessage(), false, e);
  }

  /** Ends the student's side (it answers and exits) and stops bridging. */
  @Override
  public void close() {
    if (closed) {
      return;
    }
    closed = true;
    world.removeStepListener(bridge);
    try {
      out.writeByte(Frames.END);
      out.flush();
      expect(Frames.BYE);
    } catch (IOException e) {
      throw lost(e);
    }
  }
}
