package org.jaria.sim.client;

import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.BooleanSupplier;
import org.jaria.clock.VirtualClock;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An {@link ArRobot} connected to a simulated robot in lockstep: both run on the world's virtual
 * clock, and the robot's cycle runs inside the world's steps, once per SIP (or after two cycle
 * times without one), exactly as it would on a real robot. Nothing runs unless the test advances
 * time, so every run with the same seed is identical, and a minute of robot time takes a few
 * milliseconds.
 *
 * <pre>{@code
 * try (SimulatedRobot sim = SimulatedRobot.start("office", "p3dx-sh", 1)) {
 *   ArRobot robot = sim.robot();
 *   robot.enableMotors();
 *   robot.move(1000);
 *   assertTrue(sim.runUntil(robot::isMoveDone, Duration.ofSeconds(10)));
 * }
 * }</pre>
 *
 * <p>This is the only part of the simulator that uses the client's ArRobot; the server side knows
 * nothing of it.
 */
public final class SimulatedRobot implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(SimulatedRobot.class);

  /** How long a stopped program gets to end after its thread is interrupted, ms (real time). */
  private static final long PROGRAM_JOIN_MILLIS = 2000;

  private final SimWorld world;
  private final SimRobot simRobot;
  private final ArRobot robot;
  private final boolean ownsWorld;
  private final Runnable driver = this::afterStep;
  private long lastCycleNanos;

  private SimulatedRobot(SimWorld world, SimRobot simRobot, ArRobot robot, boolean ownsWorld) {
    this.world = world;
    this.simRobot = simRobot;
    this.robot = robot;
    this.ownsWorld = ownsWorld;
  }

  /**
   * Connects a new ArRobot (named after the simulated one) to {@code simRobot} in lockstep and runs
   * the world until the handshake is done.
   *
   * @throws IllegalStateException if the robot does not connect within 30 s of virtual time
   */
  public static SimulatedRobot connect(SimWorld world, SimRobot simRobot) {
    return connect(world, simRobot, new ArRobot(simRobot.getName(), world.getClock(), true), false);
  }

  /** As {@link #connect(SimWorld, SimRobot)}, with an ArRobot you made (on the world's clock). */
  public static SimulatedRobot connect(SimWorld world, SimRobot simRobot, ArRobot robot) {
    return connect(world, simRobot, robot, false);
  }

  private static SimulatedRobot connect(
      SimWorld world, SimRobot simRobot, ArRobot robot, boolean ownsWorld) {
    if (robot.getClock() != world.getClock()) {
      throw new IllegalArgumentException(
          "the ArRobot must run on the world's clock: new ArRobot(name, world.getClock(), true)");
    }
    robot.setDeviceConnection(simRobot.connectInMemory());
    SimulatedRobot s = new SimulatedRobot(world, simRobot, robot, ownsWorld);
    world.addStepListener(s.driver);
    robot.asyncConnect();
    if (!s.runUntil(() -> !robot.isConnecting(), Duration.ofSeconds(30)) || !robot.isConnected()) {
      s.close();
      throw new IllegalStateException(
          "simulated robot did not connect: " + robot.getConnectFailure());
    }
    return s;
  }

  /**
   * A new world on a bundled map ("office", "hall") with one robot of the given model, seeded, and
   * an ArRobot connected to it. Closing the SimulatedRobot closes the world.
   */
  public static SimulatedRobot start(String bundledMap, String model, long seed) {
    SimWorld world =
        SimWorld.bundled(bundledMap, org.jaria.sim.SimOptions.builder().seed(seed).build());
    SimRobot r = world.addRobot(model);
    return connect(world, r, new ArRobot(r.getName(), world.getClock(), true), true);
  }

  private void afterStep() {
    long now = world.getClock().nanoTime();
    long fallback = TimeUnit.MILLISECONDS.toNanos(2 * robot.getCycleTime());
    if (robot.isConnecting() || robot.pollForSip() || now - lastCycleNanos >= fallback) {
      lastCycleNanos = now;
      robot.loopOnce();
    }
  }

  /** The client robot: use it as in any ARIA program. */
  public ArRobot robot() {
    return robot;
  }

  /** The simulated robot: true pose, sensor ground truth, dropping the connection. */
  public SimRobot sim() {
    return simRobot;
  }

  /** The world. */
  public SimWorld world() {
    return world;
  }

  /** Runs {@code d} of virtual time. */
  public void run(Duration d) {
    world.advance(d);
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

  /** What became of a program run with {@link #runProgram}. */
  public enum ProgramResult {
    /** The program returned. */
    FINISHED,
    /** Simulated time ran out while the program was still going. */
    TIMED_OUT,
    /** The program stopped advancing: it runs without ever waiting on the robot's clock. */
    STUCK,
    /** The program threw; see {@link #lastProgramFailure()}. */
    FAILED
  }

  private volatile Throwable programFailure;
  private volatile long stuckNanos = TimeUnit.SECONDS.toNanos(5);

  /**
   * How long {@link #runProgram} waits, in real time, for a program that neither waits on the clock
   * nor ends before calling it stuck (default 5 s).
   */
  public void setStuckTimeout(Duration d) {
    stuckNanos = d.toNanos();
  }

  /**
   * Runs a sequential program — one that commands the robot and waits, like {@code move(1000);
   * while (!robot.isMoveDone()) robot.getClock().sleepMillis(50);} — on virtual time. The program
   * runs on a thread of its own; whenever it waits on the robot's clock the world advances a tick,
   * so simulated time passes only while the program waits, and a run is still deterministic and
   * fast.
   *
   * @param program the program, given the connected robot
   * @param max the most simulated time to allow
   * @return how the program ended; a program that busy-waits without the clock is {@link
   *     ProgramResult#STUCK} after {@link #setStuckTimeout} of real time. The thread of a stuck or
   *     timed-out program is interrupted and given two seconds to end before this returns; one that
   *     ignores the interrupt is logged and left running as a daemon.
   */
  public ProgramResult runProgram(java.util.function.Consumer<ArRobot> program, Duration max) {
    VirtualClock clock = world.getVirtualClock();
    programFailure = null;
    AtomicBoolean finished = new AtomicBoolean();
    Thread t =
        new Thread(
            () -> {
              try {
                program.accept(robot);
              } catch (RuntimeException | Error e) {
                programFailure = e;
              } finally {
                finished.set(true);
                clock.wakeWatchers(); // hand control back at once
              }
            },
            "program-" + simRobot.getName());
    t.setDaemon(true);
    long end = clock.nanoTime() + max.toNanos();
    Duration stuck = Duration.ofNanos(stuckNanos);
    t.start();
    try {
      while (true) {
        // Hand-off: the program runs until it waits on the clock (or ends); only then does the
        // world move on, so simulated time passes exactly while the program waits.
        boolean waiting = clock.awaitWaiters(1, stuck, finished::get);
        if (finished.get()) {
          t.join();
          return programFailure == null ? ProgramResult.FINISHED : ProgramResult.FAILED;
        }
        if (!waiting) {
          stop(t, "is stuck: it has neither waited on the robot's clock nor ended in " + stuck);
          return ProgramResult.STUCK;
        }
        if (clock.nanoTime() >= end) {
          stop(t, "ran out of its " + max + " of simulated time");
          return ProgramResult.TIMED_OUT;
        }
        world.step();
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      t.interrupt();
      return ProgramResult.TIMED_OUT;
    }
  }

  /**
   * Interrupts the program thread and waits a bounded time for it to end; a program that ignores
   * interrupts is left running (a daemon thread) and said so.
   */
  private static void stop(Thread t, String why) throws InterruptedException {
    t.interrupt();
    t.join(PROGRAM_JOIN_MILLIS);
    if (t.isAlive()) {
      log.warn(
          "program thread {} {} and did not stop within {} ms of being interrupted; it is left"
              + " running as a daemon. Let the program check Thread.interrupted() or wait on the"
              + " robot's clock",
          t.getName(),
          why,
          PROGRAM_JOIN_MILLIS);
    } else {
      log.info("program thread {} {}; stopped", t.getName(), why);
    }
  }

  /** What the last {@link #runProgram} program threw, or null. */
  public Throwable lastProgramFailure() {
    return programFailure;
  }

  /** Disconnects the robot and stops driving it; closes the world if this object created it. */
  @Override
  public void close() {
    world.removeStepListener(driver);
    robot.close();
    if (ownsWorld) {
      world.close();
    }
  }
}
