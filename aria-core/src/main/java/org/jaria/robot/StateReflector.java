package org.jaria.robot;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayDeque;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import org.jaria.action.ArActionDesired;
import org.jaria.clock.Clock;
import org.jaria.geom.ArMath;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.DirectMotion.RotType;
import org.jaria.robot.DirectMotion.TransType;

/**
 * The velocity stage of the robot: keeps what the program asked for with motion commands ({@link
 * DirectMotion}) and what went out before ({@link ReflectionMemory}), and once per cycle asks
 * {@link StateReflection} what to send and sends it. The decision is a function over values; this
 * class only holds the state between cycles and is the one place that writes motion commands.
 *
 * <p>Setters may be called from any thread; all state is guarded by this object's monitor. Nothing
 * is written to the connection while holding it, so a slow link (a serial port at 9600 baud) never
 * keeps another thread from asking whether a move is done: a method decides under the monitor and
 * puts the commands it decided in the outbox, then writes the outbox without the monitor, holding
 * only {@link #writing}. Commands go out in the order they were decided, whichever thread writes
 * them, and a method returns only once its own commands went out.
 */
final class StateReflector {

  private final Clock clock;
  private final ArRobotPacketSender sender;
  private final Supplier<RobotStatus> status;
  private final MotionLimits limits = new MotionLimits();

  /**
   * Held while writing the outbox, so that one thread at a time takes commands from it and they
   * leave in order. Taken without the monitor, and the monitor only briefly inside it.
   */
  private final ReentrantLock writing = new ReentrantLock();

  /** Commands decided and not yet written, oldest first. */
  @GuardedBy("this")
  private final ArrayDeque<MotionCommand> outbox = new ArrayDeque<>();

  @GuardedBy("this")
  private boolean doStateReflection = true;

  @GuardedBy("this")
  private long refreshNanos = TimeUnit.MILLISECONDS.toNanos(500);

  @GuardedBy("this")
  private long precedenceMs;

  @GuardedBy("this")
  private boolean hasMoveCommand = true;

  @GuardedBy("this")
  private double vel2Divisor = 20;

  /** The settings as one value; null after a change, made again by the next cycle. */
  @GuardedBy("this")
  private StateReflection.Settings settings;

  @GuardedBy("this")
  private DirectMotion direct = DirectMotion.NONE;

  @GuardedBy("this")
  private ReflectionMemory memory = ReflectionMemory.EMPTY;

  @GuardedBy("this")
  private boolean tryingToMove;

  @GuardedBy("this")
  private double moveDoneDist = 40;

  @GuardedBy("this")
  private double headingDoneDiff = 3;

  StateReflector(Clock clock, ArRobotPacketSender sender, Supplier<RobotStatus> status) {
    this.clock = clock;
    this.sender = sender;
    this.status = status;
  }

  // ---------------------------------------------------------------- configuration

  synchronized void configure(
      boolean velMaxes, boolean accsDecs, boolean moveCommand, double vel2Div) {
    limits.configure(velMaxes, accsDecs);
    hasMoveCommand = moveCommand;
    vel2Divisor = vel2Div <= 0 ? 20 : vel2Div;
    settings = null;
  }

  /** Takes the speed limits a newly connected robot starts with. */
  void configure(ConfiguredLimits c) {
    limits.apply(c);
  }

  synchronized void setDoStateReflection(boolean on) {
    doStateReflection = on;
    settings = null;
  }

  synchronized void setRefreshMillis(long ms) {
    refreshNanos = TimeUnit.MILLISECONDS.toNanos(ms);
    settings = null;
  }

  synchronized long getRefreshMillis() {
    return TimeUnit.NANOSECONDS.toMillis(refreshNanos);
  }

  synchronized void setDirectMotionPrecedenceTime(long ms) {
    precedenceMs = Math.max(0, ms);
    settings = null;
  }

  synchronized long getDirectMotionPrecedenceTime() {
    return precedenceMs;
  }

  /** Forgets the motion commands and everything sent (a new connection). */
  synchronized void reset() {
    direct =
        direct
            .withTrans(TransType.NONE, direct.transVal())
            .withRot(RotType.NONE, direct.rotVal(), direct.rotSetTime());
    memory = memory.connected(clock.nanoTime());
  }

  /** The speed and acceleration limits (thread-safe on their own). */
  MotionLimits limits() {
    return limits;
  }

  // ---------------------------------------------------------------- motion commands

  void setVel(double v) {
    synchronized (this) {
      direct =
          direct.withTrans(
              TransType.VEL, v, direct.transVal2(), clock.nanoTime(), direct.transDistStart());
      if (!doStateReflection) {
        outbox.add(MotionCommand.of(ArCommands.VEL, StateReflection.clampShort(v)));
      }
    }
    writeOutbox();
  }

  void setVel2(double left, double right) {
    synchronized (this) {
      long now = clock.nanoTime();
      direct =
          direct
              .withTrans(TransType.VEL2, left, right, now, direct.transDistStart())
              .withRot(RotType.IGNORE, direct.rotVal(), now);
      if (!doStateReflection) {
        outbox.add(
            MotionCommand.twoBytes(
                ArCommands.VEL2,
                StateReflection.vel2Byte(left, vel2Divisor),
                StateReflection.vel2Byte(right, vel2Divisor)));
      }
    }
    writeOutbox();
  }

  void move(double distance) {
    synchronized (this) {
      direct =
          direct.withTrans(
              TransType.DIST_NEW,
              distance,
              direct.transVal2(),
              clock.nanoTime(),
              status.get().pose());
      if (!doStateReflection) {
        outbox.add(MotionCommand.of(ArCommands.MOVE, StateReflection.clampShort(distance)));
        direct = direct.withTrans(TransType.DIST, distance);
      }
    }
    writeOutbox();
  }

  synchronized boolean isMoveDone(double delta) {
    if (Math.abs(delta) < 0.001) {
      delta = moveDoneDist;
    }
    DirectMotion d = direct;
    if (d.transType() != TransType.DIST && d.transType() != TransType.DIST_NEW) {
      return true;
    }
    double gone = d.transDistStart().findDistanceTo(status.get().pose());
    return Math.abs(gone - Math.abs(d.transVal())) < delta;
  }

  synchronized void setMoveDoneDist(double d) {
    moveDoneDist = d;
  }

  synchronized double getMoveDoneDist() {
    return moveDoneDist;
  }

  void setRotVel(double v) {
    synchronized (this) {
      direct = direct.withRot(RotType.VEL, v, clock.nanoTime());
      if (!doStateReflection) {
        outbox.add(MotionCommand.of(ArCommands.RVEL, StateReflection.clampShort(v)));
      }
    }
    writeOutbox();
  }

  void setHeading(double heading) {
    double h = ArMath.fixAngle(heading);
    synchronized (this) {
      direct = direct.withRot(RotType.HEADING, h, clock.nanoTime());
      if (!doStateReflection) {
        outbox.add(
            MotionCommand.of(ArCommands.HEAD, StateReflection.robotHeading(h, status.get())));
      }
    }
    writeOutbox();
  }

  void setDeltaHeading(double delta) {
    setHeading(status.get().pose().th() + delta);
  }

  synchronized boolean isHeadingDone(double delta) {
    if (Math.abs(delta) < 0.001) {
      delta = headingDoneDiff;
    }
    if (direct.rotType() != RotType.HEADING) {
      return true;
    }
    return Math.abs(ArMath.subAngle(status.get().pose().th(), direct.rotVal())) < delta;
  }

  synchronized void setHeadingDoneDiff(double d) {
    headingDoneDiff = d;
  }

  synchronized double getHeadingDoneDiff() {
    return headingDoneDiff;
  }

  /** Stops both axes at once (STOP) and remembers that zero is what is wanted. */
  void stop() {
    synchronized (this) {
      outbox.add(MotionCommand.of(ArCommands.STOP));
      long now = clock.nanoTime();
      direct =
          direct
              .withTrans(TransType.VEL, 0, direct.transVal2(), now, direct.transDistStart())
              .withRot(RotType.VEL, 0, now);
      memory = memory.stopped(now);
    }
    writeOutbox();
  }

  synchronized void clearDirectMotion() {
    direct =
        direct
            .withTrans(TransType.NONE, direct.transVal())
            .withRot(RotType.NONE, direct.rotVal(), direct.rotSetTime());
    memory = memory.directCleared();
  }

  synchronized boolean isDirectMotion() {
    long now = clock.nanoTime();
    long p = TimeUnit.MILLISECONDS.toNanos(precedenceMs);
    return hasPrecedence(direct.transType() != TransType.NONE, direct.transSetTime(), now, p)
        || hasPrecedence(direct.rotType() != RotType.NONE, direct.rotSetTime(), now, p);
  }

  private static boolean hasPrecedence(boolean set, long setTime, long now, long precedenceNanos) {
    return set && (precedenceNanos == 0 || now - setTime < precedenceNanos);
  }

  synchronized boolean isTryingToMove() {
    return tryingToMove;
  }

  // ---------------------------------------------------------------- the cycle

  /**
   * Decides what this cycle sends and sends it. {@code desired} is the actions' resolved desire (no
   * strength anywhere if there are no actions); the latest status carries the encoder→global
   * transform a HEAD needs.
   */
  void reflect(ArActionDesired desired) {
    decide(desired);
    writeOutbox();
  }

  private synchronized void decide(ArActionDesired desired) {
    MotionLimits.Values v = limits.values();
    if (settings == null || !settings.limits().equals(v)) {
      settings =
          new StateReflection.Settings(
              doStateReflection,
              refreshNanos,
              TimeUnit.MILLISECONDS.toNanos(precedenceMs),
              hasMoveCommand,
              vel2Divisor,
              v);
    }
    StateReflection.Inputs in =
        new StateReflection.Inputs(clock.nanoTime(), direct, desired, status.get(), settings);
    CycleCommands c = StateReflection.decide(in, memory);
    direct = c.direct();
    memory = c.memory();
    if (doStateReflection) {
      tryingToMove = c.tryingToMove();
    }
    List<MotionCommand> commands = c.commands();
    for (int i = 0; i < commands.size(); i++) {
      outbox.add(commands.get(i));
    }
  }

  // ---------------------------------------------------------------- writing

  /**
   * Writes every command in the outbox, oldest first, without holding the monitor. Called after
   * each decision, never from inside a synchronized block: if another thread is writing, this one
   * waits for it and then writes what is left (its own commands included, unless the other thread
   * already wrote them).
   */
  private void writeOutbox() {
    writing.lock();
    try {
      MotionCommand m;
      while ((m = nextToWrite()) != null) {
        m.sendWith(sender);
      }
    } finally {
      writing.unlock();
    }
  }

  private synchronized MotionCommand nextToWrite() {
    return outbox.poll();
  }
}
