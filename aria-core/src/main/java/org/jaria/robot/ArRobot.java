package org.jaria.robot;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArPriorityResolver;
import org.jaria.action.ArResolver;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.ArSensorReading;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot: its connection, its state and its cycle (ARIA's {@code ArRobot}).
 *
 * <p>Typical use, as in ARIA:
 *
 * <pre>{@code
 * ArRobot robot = new ArRobot();
 * robot.setDeviceConnection(new ArTcpConnection("localhost", 8101));
 * if (!robot.blockingConnect()) { ... }
 * robot.runAsync(true);
 * robot.enableMotors();
 * robot.setVel(200);
 * }</pre>
 *
 * <p><b>The cycle.</b> Every standard SIP (ten a second) starts one cycle: packet handlers, then
 * sensor-interpretation tasks, then action resolution, then state reflection (which sends the
 * motion commands), then user tasks. {@link #runAsync} runs cycles on a thread of their own; {@link
 * #run} on the caller's thread; {@link #loopOnce} runs exactly one, for programs (and simulators in
 * lockstep) that drive the loop themselves. If no SIP comes within two cycle times the cycle runs
 * anyway.
 *
 * <p><b>Threads.</b> Every getter may be called from any thread: the robot publishes an immutable
 * {@link RobotStatus} after each SIP, and getters read the latest one. Motion commands and direct
 * commands may also be sent from any thread. The cycle holds the robot's lock ({@link #lock()})
 * while it runs tasks; hold it yourself to keep the cycle from running between two of your calls.
 * If your code holds it longer than a cycle time, that cycle's tasks are skipped (and a warning
 * logged) but the robot is still kept alive with PULSEs.
 *
 * <p><b>Inside.</b> This class is the ARIA-style facade; the work is done by stages that each own
 * their state and pass data one way: {@code RobotLink} (connection, packet queue, handshake,
 * timeouts) hands packets to {@code PacketRouter} (the packet handlers), whose SIP handler in
 * {@code StatusStage} turns them through {@code SipProcessor} into the {@link RobotStatus} the
 * getters read. Going out, {@code ActionStage} resolves the actions' desires, {@code
 * StateReflection} decides the motion commands of the cycle, and {@code StateReflector} sends them
 * through the one {@link ArRobotPacketSender}.
 */
public class ArRobot implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArRobot.class);

  /** The clock every wait and timeout of this robot uses. */
  protected final Clock clock;

  private final String name;
  private final DropCounters drops;
  private final StatusStage state;
  private final ArRobotPacketSender sender;
  private final StateReflector motion;
  private final ActionStage actions = new ActionStage();
  private final CopyOnWriteArrayList<ArRangeDevice> rangeDevices = new CopyOnWriteArrayList<>();
  private final ReentrantLock robotLock = new ReentrantLock();
  private final TaskList sensorInterpTasks = new TaskList("sensor interpretation");
  private final TaskList userTasks = new TaskList("user");
  private final PacketRouter router = new PacketRouter();
  private final Callbacks runExitCBs = new Callbacks("run exit");
  final RobotLink link;
  private final RunLoop runLoop;
  private final AtomicLong counter = new AtomicLong();
  private volatile long cycleTimeMs = 100;
  private volatile long cycleWarningTimeMs = 250;
  private volatile boolean cycleChained = true;
  private volatile long lastCycleNanos;
  private final AtomicLong lockWarnings = new AtomicLong();
  private final AtomicLong overrunWarnings = new AtomicLong();

  /** A robot with the default name, timed by the system clock. */
  public ArRobot() {
    this("robot", Clock.system(), true);
  }

  /** A robot with a name (used in thread names and logs), timed by the system clock. */
  public ArRobot(String name) {
    this(name, Clock.system(), true);
  }

  /**
   * A robot timed by {@code clock} (a {@link org.jaria.clock.VirtualClock} in tests).
   *
   * @param doStateReflection if false, motion commands are sent once when called instead of being
   *     kept and re-sent by the cycle (ARIA's constructor flag)
   */
  public ArRobot(String name, Clock clock, boolean doStateReflection) {
    this.clock = clock;
    this.name = name;
    this.drops = new DropCounters(name);
    this.state = new StatusStage(clock, ArRobotParams.defaults(), drops);
    this.sender = new ArRobotPacketSender(clock);
    this.motion = new StateReflector(clock, sender, state::status);
    this.runLoop = new RunLoop(name, clock, new Cycle(), runExitCBs::invokeAll);
    this.link =
        new RobotLink(
            clock,
            sender,
            drops,
            router,
            robotLock,
            this::getCycleTime,
            runLoop::isRunning,
            new LinkEvents());
    motion.setDoStateReflection(doStateReflection);
    router.add(p -> state.handleSip(p, counter.get()), ArListPos.LAST);
    router.add(state::handleEncoderPacket, ArListPos.LAST);
    router.add(state::handleIoPacket, ArListPos.LAST);
  }

  /** What the robot's stages do when its link changes: each takes what it needs as a value. */
  private final class LinkEvents implements RobotLink.Events {
    @Override
    public void connecting() {
      state.reset();
      motion.reset();
    }

    @Override
    public void identified(ArRobotParams p) {
      state.setParams(p);
      motion.configure(
          p.hasSettableVelMaxes(), p.hasSettableAccsDecs(), p.hasMoveCommand(), p.getVel2Divisor());
    }

    @Override
    public void configured(ConfiguredLimits limits) {
      motion.configure(limits);
    }
  }

  /** What the run loop runs: this robot's cycle, and the wait for the input of the next one. */
  private final class Cycle implements RunLoop.Cycle {
    @Override
    public long cycleTimeMs() {
      return cycleTimeMs;
    }

    @Override
    public boolean awaitInput(long start, long cycleNanos) {
      if (link.isConnecting()) {
        link.waitWhileConnecting(start + cycleNanos);
        return true;
      }
      if (link.isConnected() && cycleChained) {
        link.waitForSip(start + 2 * cycleNanos);
        return true;
      }
      return false;
    }

    @Override
    public void runOnce() {
      loopOnce();
    }

    @Override
    public boolean linked() {
      return link.isConnected() || link.isConnecting();
    }
  }

  /** The robot's name as given to the constructor. */
  public String getName() {
    return name;
  }

  // ================================================================ connection

  /** Sets the connection to the robot (TCP, serial or pipe); it is opened when connecting. */
  public void setDeviceConnection(ArDeviceConnection c) {
    link.setDeviceConnection(c);
  }

  /** The connection to the robot, or null. */
  public ArDeviceConnection getDeviceConnection() {
    return link.getDeviceConnection();
  }

  /**
   * Connects to the robot, waiting until connected or failed (a few seconds at most). If the
   * robot's cycle is already running on another thread, the connection is made there and this
   * method waits for it.
   *
   * @return whether the robot is connected
   */
  public boolean blockingConnect() {
    return link.blockingConnect();
  }

  /**
   * Starts connecting without waiting: the running cycle (or the next {@link #loopOnce} calls)
   * carry the handshake forward. Watch {@link #isConnected()} or add a connect callback.
   *
   * @return false if there is no connection to use
   */
  public boolean asyncConnect() {
    return link.asyncConnect();
  }

  /** Whether the robot is connected. */
  public boolean isConnected() {
    return link.isConnected();
  }

  /** Whether a connection attempt is under way. */
  public boolean isConnecting() {
    return link.isConnecting();
  }

  /** Why the last connection attempt failed, or an empty string. */
  public String getConnectFailure() {
    return link.failure();
  }

  /** Sends CLOSE and closes the connection; the disconnect-normally callbacks run. */
  public boolean disconnect() {
    return link.disconnect();
  }

  /** The robot's name from the handshake. */
  public String getRobotName() {
    return link.robotName();
  }

  /** The robot's type from the handshake, e.g. "Pioneer". */
  public String getRobotType() {
    return link.robotType();
  }

  /** The robot's subtype from the handshake, lower-cased, e.g. "p3dx-sh". */
  public String getRobotSubType() {
    return link.robotSubType();
  }

  /** The CONFIGpac received when connecting, or null. */
  public ArConfigPacket getOrigRobotConfig() {
    return link.config();
  }

  /** The parameters in use (from the robot's subtype and name once connected). */
  public ArRobotParams getRobotParams() {
    return state.params();
  }

  /**
   * Where user parameter files ({@code <subtype>.p}, {@code <name>.p}) are looked for; by default
   * {@code $JARIA_PARAMS}, else {@code ~/.jaria/params}. Null uses only the bundled files.
   */
  public void setParamsDirectory(Path dir) {
    link.setParamsDirectory(dir);
  }

  /** Where user parameter files are looked for (see {@link #setParamsDirectory}); may be null. */
  public Path getParamsDirectory() {
    return link.paramsDirectory();
  }

  /**
   * How long without any packet before the connection counts as lost, ms (default 8000; 0 never).
   */
  public void setConnectionTimeoutTime(long ms) {
    link.setTimeoutMs(ms);
  }

  /** The connection-lost timeout, ms. */
  public long getConnectionTimeoutTime() {
    return link.timeoutMs();
  }

  /** Commands sent since the robot was created. */
  public long getPacketsSent() {
    return sender.getPacketsSent();
  }

  /** The object that writes commands; its tap sees every packet sent. */
  public ArRobotPacketSender getPacketSender() {
    return sender;
  }

  /** Runs when a connection is made. */
  public void addConnectCB(Runnable cb) {
    link.connectCBs.add(cb);
  }

  /** Removes a connect callback. */
  public void remConnectCB(Runnable cb) {
    link.connectCBs.remove(cb);
  }

  /** Runs when a connection attempt fails. */
  public void addFailedConnectCB(Runnable cb) {
    link.failedConnectCBs.add(cb);
  }

  /** Removes a failed-connect callback. */
  public void remFailedConnectCB(Runnable cb) {
    link.failedConnectCBs.remove(cb);
  }

  /** Runs when the program disconnects on purpose. */
  public void addDisconnectNormallyCB(Runnable cb) {
    link.disconnectNormallyCBs.add(cb);
  }

  /** Removes a disconnect-normally callback. */
  public void remDisconnectNormallyCB(Runnable cb) {
    link.disconnectNormallyCBs.remove(cb);
  }

  /** Runs when the connection is lost (no packets, broken link, controller reset). */
  public void addDisconnectOnErrorCB(Runnable cb) {
    link.disconnectOnErrorCBs.add(cb);
  }

  /** Removes a disconnect-on-error callback. */
  public void remDisconnectOnErrorCB(Runnable cb) {
    link.disconnectOnErrorCBs.remove(cb);
  }

  /** Runs when {@link #run} / {@link #runAsync} ends. */
  public void addRunExitCB(Runnable cb) {
    runExitCBs.add(cb);
  }

  /** Removes a run-exit callback. */
  public void remRunExitCB(Runnable cb) {
    runExitCBs.remove(cb);
  }

  // ================================================================ the cycle

  /**
   * Runs the cycle on the calling thread until {@link #stopRunning()}.
   *
   * @param stopRunIfNotConnected also stop when the robot is (or becomes) disconnected
   */
  public void run(boolean stopRunIfNotConnected) {
    runLoop.run(stopRunIfNotConnected);
  }

  /** Runs the cycle on a new thread named after the robot; returns at once. */
  public void runAsync(boolean stopRunIfNotConnected) {
    runLoop.runAsync(stopRunIfNotConnected);
  }

  /** Asks the cycle to stop; it ends within about two cycle times. */
  public void stopRunning() {
    runLoop.stopRunning();
  }

  /** Whether the cycle is running. */
  public boolean isRunning() {
    return runLoop.isRunning();
  }

  /** Waits until the cycle has stopped (at once if it is not running). */
  public void waitForRunExit() throws InterruptedException {
    runLoop.waitForRunExit();
  }

  /**
   * Runs one cycle now: reads what has arrived (without waiting), then packet handlers, sensor
   * interpretation, actions, state reflection and user tasks. While a connection is being made it
   * advances the handshake instead.
   */
  public void loopOnce() {
    long start = clock.nanoTime();
    long realStart = System.nanoTime();
    if (link.stepConnecting(start)) {
      counter.incrementAndGet();
      return;
    }
    if (isConnected()) {
      link.readAvailable(start);
    }
    boolean locked;
    try {
      locked = robotLock.tryLock(Math.max(1, cycleTimeMs), TimeUnit.MILLISECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      return;
    }
    if (!locked) {
      keepAliveWithoutLock(start);
      return;
    }
    try {
      link.handOnQueued();
      link.checkTimeout(clock.nanoTime());
      sensorInterpTasks.runAll();
      ArActionDesired desired = actions.resolve(this, isConnected());
      if (isConnected()) {
        motion.reflect(desired);
      }
      userTasks.runAll();
    } finally {
      robotLock.unlock();
    }
    counter.incrementAndGet();
    lastCycleNanos = System.nanoTime() - realStart;
    // Measured on the robot's clock, like every other time in the robot: on a virtual clock a
    // cycle takes no time unless a task makes time pass, so runs stay deterministic.
    long took = clock.nanoTime() - start;
    if (cycleWarningTimeMs > 0 && took > TimeUnit.MILLISECONDS.toNanos(cycleWarningTimeMs)) {
      warnRarely(
          overrunWarnings.incrementAndGet(),
          "cycle took {} ms, more than the {} ms warning time: a task is too slow",
          TimeUnit.NANOSECONDS.toMillis(took),
          cycleWarningTimeMs);
    }
  }

  /**
   * Reads what has arrived, without waiting, and says whether a standard SIP is among it — for
   * programs that drive {@link #loopOnce()} themselves and want ARIA's one cycle per SIP (a
   * simulator in lockstep does this). Call it only from the thread that runs the cycles.
   */
  public boolean pollForSip() {
    if (isConnected()) {
      link.readAvailable(clock.nanoTime());
    }
    return link.hasSip();
  }

  private void keepAliveWithoutLock(long now) {
    warnRarely(
        lockWarnings.incrementAndGet(),
        "skipped a cycle: user code held the robot lock for more than {} ms (cycle time {} ms)",
        cycleTimeMs,
        cycleTimeMs);
    if (isConnected() && now - sender.getLastSentNanos() > TimeUnit.MILLISECONDS.toNanos(500)) {
      sender.com(ArCommands.PULSE.getNumber());
    }
  }

  private static void warnRarely(long n, String format, Object a, Object b) {
    if (n == 1 || n % 100 == 0) {
      log.warn(format + " (#" + n + ")", a, b);
    }
  }

  /** Adds a packet handler at the end of the list (after the robot's own handlers). */
  public void addPacketHandler(ArPacketHandler h) {
    addPacketHandler(h, ArListPos.LAST);
  }

  /** Adds a packet handler at the front (asked before the robot's own) or the end. */
  public void addPacketHandler(ArPacketHandler h, ArListPos pos) {
    router.add(h, pos);
  }

  /** Removes a packet handler. */
  public void remPacketHandler(ArPacketHandler h) {
    router.remove(h);
  }

  /**
   * Adds (or replaces, by name) a sensor-interpretation task; higher positions run first. Range
   * devices and localization use these.
   */
  public ArSyncTask addSensorInterpTask(String taskName, int position, Runnable task) {
    return sensorInterpTasks.add(taskName, position, task);
  }

  /** Removes a sensor-interpretation task by name. */
  public boolean remSensorInterpTask(String taskName) {
    return sensorInterpTasks.remove(taskName);
  }

  /** Adds (or replaces, by name) a user task; higher positions run first. */
  public ArSyncTask addUserTask(String taskName, int position, Runnable task) {
    return userTasks.add(taskName, position, task);
  }

  /** Removes a user task by name. */
  public boolean remUserTask(String taskName) {
    return userTasks.remove(taskName);
  }

  /** The sensor-interpretation task with this name, or null. */
  public ArSyncTask findSensorInterpTask(String taskName) {
    return sensorInterpTasks.find(taskName);
  }

  /** The user task with this name, or null. */
  public ArSyncTask findUserTask(String taskName) {
    return userTasks.find(taskName);
  }

  /** The user tasks in running order. */
  public List<ArSyncTask> getUserTasks() {
    return userTasks.snapshot();
  }

  /** The sensor-interpretation tasks in running order. */
  public List<ArSyncTask> getSensorInterpTasks() {
    return sensorInterpTasks.snapshot();
  }

  /**
   * The cycle as a tree, as ARIA's {@code getSyncTaskRoot()} shows it: "SyncTasks" with "Packet
   * Handler" (85), the "Sensor Interp" branch (65) with its tasks, "Action Handler" (55), "State
   * Reflector" (45) and the "User Tasks" branch (25) with its tasks. A snapshot: ask again after
   * adding or removing tasks. {@code System.out.print(robot.getSyncTaskRoot())} prints it.
   */
  public SyncTaskView getSyncTaskRoot() {
    return new SyncTaskView(
        "SyncTasks",
        0,
        true,
        null,
        List.of(
            SyncTaskView.step("Packet Handler", 85),
            SyncTaskView.branch("Sensor Interp", 65, sensorInterpTasks.snapshot()),
            SyncTaskView.step("Action Handler", 55),
            SyncTaskView.step("State Reflector", 45),
            SyncTaskView.branch("User Tasks", 25, userTasks.snapshot())));
  }

  /** Locks the robot: the cycle's tasks do not run until {@link #unlock()}. */
  public void lock() {
    robotLock.lock();
  }

  /** Tries to lock the robot without waiting. */
  public boolean tryLock() {
    return robotLock.tryLock();
  }

  /** Unlocks the robot. */
  public void unlock() {
    robotLock.unlock();
  }

  /** Cycles run so far (ARIA's counter, used to tell new sensor readings from old). */
  public long getCounter() {
    return counter.get();
  }

  /** Sets the cycle time, ms (default 100, the SIP cycle). */
  public void setCycleTime(long ms) {
    if (ms <= 0) {
      throw new IllegalArgumentException("cycle time must be positive, got " + ms);
    }
    cycleTimeMs = ms;
  }

  /** The cycle time, ms. */
  public long getCycleTime() {
    return cycleTimeMs;
  }

  /**
   * A cycle longer than this, on the robot's clock, logs a warning and is counted ({@link
   * #getCycleOverrunCount()}), ms (default 250; 0 never).
   */
  public void setCycleWarningTime(long ms) {
    cycleWarningTimeMs = ms;
  }

  /** The cycle warning time, ms. */
  public long getCycleWarningTime() {
    return cycleWarningTimeMs;
  }

  /** Whether each cycle waits for a SIP (true, default) or just runs every cycle time. */
  public void setCycleChained(boolean chained) {
    cycleChained = chained;
  }

  /** Whether cycles are chained to SIP arrival. */
  public boolean isCycleChained() {
    return cycleChained;
  }

  /** Real time the last cycle's tasks took, ns. */
  public long getLastCycleNanos() {
    return lastCycleNanos;
  }

  /**
   * How many cycles took longer than the {@link #setCycleWarningTime cycle warning time} on the
   * robot's clock (each logged a warning, or every hundredth after the first).
   */
  public long getCycleOverrunCount() {
    return overrunWarnings.get();
  }

  /** How many cycles were skipped because user code held the robot's lock too long. */
  public long getSkippedCycleCount() {
    return lockWarnings.get();
  }

  // ================================================================ state (from the latest SIP)

  /** The clock this robot runs on. */
  public Clock getClock() {
    return clock;
  }

  /** Packets dropped on the way in, by reason. */
  public DropCounters getDropCounters() {
    return drops;
  }

  /** Everything the last SIP said, as one consistent snapshot. */
  public RobotStatus getStatus() {
    return state.status();
  }

  /** Global pose: odometry corrected by the encoder→global transform (localization). */
  public ArPose getPose() {
    return state.status().pose();
  }

  /** Global x, mm. */
  public double getX() {
    return state.status().pose().x();
  }

  /** Global y, mm. */
  public double getY() {
    return state.status().pose().y();
  }

  /** Global heading, degrees in (−180, 180]. */
  public double getTh() {
    return state.status().pose().th();
  }

  /** Odometry pose (corrected by a gyro if one is attached). */
  public ArPose getEncoderPose() {
    return state.status().encoderPose();
  }

  /** Odometry pose exactly as the wheels report it. */
  public ArPose getRawEncoderPose() {
    return state.status().rawEncoderPose();
  }

  /** Translational velocity, mm/s. */
  public double getVel() {
    return state.status().vel();
  }

  /** Rotational velocity, deg/s (+ counter-clockwise). */
  public double getRotVel() {
    return state.status().rotVel();
  }

  /** Left wheel velocity, mm/s. */
  public double getLeftVel() {
    return state.status().leftVel();
  }

  /** Right wheel velocity, mm/s. */
  public double getRightVel() {
    return state.status().rightVel();
  }

  /** Battery voltage, V. */
  public double getBatteryVoltage() {
    return state.status().batteryVoltage();
  }

  /** Battery voltage from the 16-bit field (for batteries above 25.5 V), V. */
  public double getRealBatteryVoltage() {
    return state.status().realBatteryVoltage();
  }

  /** The raw stall and bumper word: bit 0 left stall, bit 8 right stall, others bumpers. */
  public int getStallValue() {
    return state.status().stallValue();
  }

  /** Whether the left motor is stalled. */
  public boolean isLeftMotorStalled() {
    return (state.status().stallValue() & 0x1) != 0;
  }

  /** Whether the right motor is stalled. */
  public boolean isRightMotorStalled() {
    return (state.status().stallValue() & 0x100) != 0;
  }

  /**
   * Front bumper bits: bits 9..15 of the stall word (the right motor's byte, as ARIA reads it),
   * shifted down so that bumper 0 — the leftmost — is bit 0.
   */
  public int getFrontBumpers() {
    return (state.status().stallValue() >> 9) & 0x7F;
  }

  /** Rear bumper bits: bits 1..7 of the stall word, shifted down so bumper 0 is bit 0. */
  public int getRearBumpers() {
    return (state.status().stallValue() >> 1) & 0x7F;
  }

  /** Heading setpoint relative to the current heading, degrees. */
  public double getControl() {
    return state.status().control();
  }

  /** The SIP flags word. */
  public int getFlags() {
    return state.status().flags();
  }

  /** Whether the motors are enabled. */
  public boolean areMotorsEnabled() {
    return (state.status().flags() & 0x1) != 0;
  }

  /** Whether any sonar array is enabled. */
  public boolean areSonarsEnabled() {
    return (state.status().flags() & 0x1E) != 0;
  }

  /** Whether the emergency stop button is pressed. */
  public boolean isEStopPressed() {
    return (state.status().flags() & 0x20) != 0;
  }

  /** Whether the robot says it is moving (SIP type 0x33). */
  public boolean isMoving() {
    return state.status().moving();
  }

  /** Compass heading, degrees (0 when there is no compass). */
  public int getCompass() {
    return state.status().compass();
  }

  /** The analog port selected with ADSEL. */
  public int getAnalogPortSelected() {
    return state.status().anPort();
  }

  /** The selected analog input, 0..255 for 0..5 V. */
  public int getAnalog() {
    return state.status().analog();
  }

  /** The digital inputs byte. */
  public int getDigIn() {
    return state.status().digIn();
  }

  /** The digital outputs byte. */
  public int getDigOut() {
    return state.status().digOut();
  }

  /** Gripper state bits (see {@link org.jaria.protocol.packets.GripState}). */
  public int getGripState() {
    return state.status().gripState();
  }

  /** Charge state: −1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float. */
  public int getChargeState() {
    return state.status().chargeState();
  }

  /** Fault flags (0 when the firmware does not report them). */
  public int getFaultFlags() {
    return state.status().faultFlags();
  }

  /** Distance driven since connecting, mm. */
  public double getOdometerDistance() {
    return state.status().odometerDistance();
  }

  /** Degrees turned since connecting. */
  public double getOdometerDegrees() {
    return state.status().odometerDegrees();
  }

  /** Left encoder count from the last ENCODERpac (request them first). */
  public int getLeftEncoder() {
    return state.encoders().left();
  }

  /** Right encoder count from the last ENCODERpac. */
  public int getRightEncoder() {
    return state.encoders().right();
  }

  /** Number of digital-input bytes in the last IOpac. */
  public int getIODigInSize() {
    return state.io().digIn().length;
  }

  /** Digital-input byte {@code n} of the last IOpac (request them first), 0 if absent. */
  public int getIODigIn(int n) {
    int[] v = state.io().digIn();
    return n >= 0 && n < v.length ? v[n] : 0;
  }

  /** Digital-output byte {@code n} of the last IOpac, 0 if absent. */
  public int getIODigOut(int n) {
    int[] v = state.io().digOut();
    return n >= 0 && n < v.length ? v[n] : 0;
  }

  /** Number of analog inputs in the last IOpac. */
  public int getIOAnalogSize() {
    return state.io().analog().length;
  }

  /** Analog input {@code n} of the last IOpac, 0..1023, 0 if absent. */
  public int getIOAnalog(int n) {
    int[] v = state.io().analog();
    return n >= 0 && n < v.length ? v[n] : 0;
  }

  // ---------------------------------------------------------------- sonar

  /** Number of sonar transducers, from the robot's parameters. */
  public int getNumSonar() {
    return state.status().sonars().size();
  }

  /** Range of sonar {@code num}, mm; −1 if it never reported or does not exist. */
  public int getSonarRange(int num) {
    List<ArSensorReading> s = state.status().sonars();
    return num >= 0 && num < s.size() ? s.get(num).range() : -1;
  }

  /** Whether sonar {@code num} reported in the SIP of the current cycle. */
  public boolean isSonarNew(int num) {
    List<ArSensorReading> s = state.status().sonars();
    return num >= 0 && num < s.size() && s.get(num).counterTaken() == state.status().counter();
  }

  /** The latest reading of sonar {@code num}, or null if there is no such sonar. */
  public ArSensorReading getSonarReading(int num) {
    List<ArSensorReading> s = state.status().sonars();
    return num >= 0 && num < s.size() ? s.get(num) : null;
  }

  /**
   * The number of the sonar with the shortest range among those facing between {@code startAngle}
   * and {@code endAngle} (counter-clockwise, degrees); −1 if none faces there.
   */
  public int getClosestSonarNumber(double startAngle, double endAngle) {
    List<ArSensorReading> s = state.status().sonars();
    int best = -1;
    int bestRange = 0;
    for (int i = 0; i < s.size(); i++) {
      ArSensorReading r = s.get(i);
      // Sonars that never reported (range -1) are not "closest" (ARIA would pick them).
      if (r.range() >= 0
          && angleBetween(r.sensorTh(), startAngle, endAngle)
          && (best < 0 || r.range() < bestRange)) {
        best = i;
        bestRange = r.range();
      }
    }
    return best;
  }

  /** The shortest range among sonars facing between the angles, mm; −1 if none. */
  public int getClosestSonarRange(double startAngle, double endAngle) {
    int n = getClosestSonarNumber(startAngle, endAngle);
    return n < 0 ? -1 : getSonarRange(n);
  }

  /**
   * Whether {@code angle} lies in the sector from {@code start} counter-clockwise to {@code end}.
   */
  static boolean angleBetween(double angle, double start, double end) {
    angle = ArMath.fixAngle(angle);
    start = ArMath.fixAngle(start);
    end = ArMath.fixAngle(end);
    if (start < end) {
      return angle >= start && angle <= end;
    }
    return angle >= start || angle <= end;
  }

  // ---------------------------------------------------------------- geometry from parameters

  /** Robot radius, mm (from the parameters). */
  public double getRobotRadius() {
    return state.params().getRobotRadius();
  }

  /** Robot width, mm. */
  public double getRobotWidth() {
    return state.params().getRobotWidth();
  }

  /** Robot length, mm. */
  public double getRobotLength() {
    return state.params().getRobotLength();
  }

  /** Distance from the centre of rotation to the front, mm. */
  public double getRobotLengthFront() {
    return state.params().getRobotLengthFront();
  }

  /** Distance from the centre of rotation to the rear, mm. */
  public double getRobotLengthRear() {
    return state.params().getRobotLengthRear();
  }

  // ---------------------------------------------------------------- motion commands

  /** Drives at {@code mmPerSec} (negative backwards). */
  public void setVel(double mmPerSec) {
    motion.setVel(mmPerSec);
  }

  /** Drives each wheel at its own speed, mm/s (sent as VEL2, in Vel2Divisor steps). */
  public void setVel2(double leftMmPerSec, double rightMmPerSec) {
    motion.setVel2(leftMmPerSec, rightMmPerSec);
  }

  /** Turns at {@code degPerSec} (+ counter-clockwise). */
  public void setRotVel(double degPerSec) {
    motion.setRotVel(degPerSec);
  }

  /** Turns to the global heading {@code degrees}, the shorter way round. */
  public void setHeading(double degrees) {
    motion.setHeading(degrees);
  }

  /** Turns by {@code degrees} from the current heading (+ counter-clockwise). */
  public void setDeltaHeading(double degrees) {
    motion.setDeltaHeading(degrees);
  }

  /** Drives {@code mm} forward (negative backwards) and stops. */
  public void move(double mm) {
    motion.move(mm);
  }

  /** Whether the last {@link #move} is done, within the move-done distance (default 40 mm). */
  public boolean isMoveDone() {
    return motion.isMoveDone(0);
  }

  /** Whether the last {@link #move} is done within {@code delta} mm. */
  public boolean isMoveDone(double delta) {
    return motion.isMoveDone(delta);
  }

  /** Whether the last heading command is done, within the heading-done difference (3°). */
  public boolean isHeadingDone() {
    return motion.isHeadingDone(0);
  }

  /** Whether the last heading command is done within {@code delta} degrees. */
  public boolean isHeadingDone(double delta) {
    return motion.isHeadingDone(delta);
  }

  /** Sets the default tolerance of {@link #isMoveDone()}, mm. */
  public void setMoveDoneDist(double mm) {
    motion.setMoveDoneDist(mm);
  }

  /** The default tolerance of {@link #isMoveDone()}, mm. */
  public double getMoveDoneDist() {
    return motion.getMoveDoneDist();
  }

  /** Sets the default tolerance of {@link #isHeadingDone()}, degrees. */
  public void setHeadingDoneDiff(double degrees) {
    motion.setHeadingDoneDiff(degrees);
  }

  /** The default tolerance of {@link #isHeadingDone()}, degrees. */
  public double getHeadingDoneDiff() {
    return motion.getHeadingDoneDiff();
  }

  /** Stops translation and rotation now (STOP), and keeps asking for zero speed. */
  public void stop() {
    motion.stop();
  }

  /** Gives the wheels back to the actions: forgets the motion commands. */
  public void clearDirectMotion() {
    motion.clearDirectMotion();
  }

  /** Whether motion commands currently take precedence over actions. */
  public boolean isDirectMotion() {
    return motion.isDirectMotion();
  }

  /**
   * How long a motion command keeps precedence over actions, ms; 0 (the default) means until {@link
   * #clearDirectMotion()}.
   */
  public void setDirectMotionPrecedenceTime(long ms) {
    motion.setDirectMotionPrecedenceTime(ms);
  }

  /** The direct-motion precedence time, ms (0 = until cleared). */
  public long getDirectMotionPrecedenceTime() {
    return motion.getDirectMotionPrecedenceTime();
  }

  /** How often unchanged motion commands are re-sent, ms (default 500). */
  public void setStateReflectionRefreshTime(long ms) {
    motion.setRefreshMillis(ms);
  }

  /** The state-reflection refresh time, ms. */
  public long getStateReflectionRefreshTime() {
    return motion.getRefreshMillis();
  }

  /** Whether the last cycle's commands asked the robot to move. */
  public boolean isTryingToMove() {
    return motion.isTryingToMove();
  }

  // ---------------------------------------------------------------- limits

  /** Maximum translational velocity for motion commands and actions, mm/s. */
  public boolean setTransVelMax(double mmPerSec) {
    return motion.limits().setTransVelMax(mmPerSec);
  }

  /** The maximum translational velocity, mm/s. */
  public double getTransVelMax() {
    return motion.limits().getTransVelMax();
  }

  /** Maximum rotational velocity, deg/s. */
  public boolean setRotVelMax(double degPerSec) {
    return motion.limits().setRotVelMax(degPerSec);
  }

  /** The maximum rotational velocity, deg/s. */
  public double getRotVelMax() {
    return motion.limits().getRotVelMax();
  }

  /** Translational acceleration, mm/s². */
  public void setTransAccel(double a) {
    motion.limits().setTransAccel(a);
  }

  /** The translational acceleration, mm/s². */
  public double getTransAccel() {
    return motion.limits().getTransAccel();
  }

  /** Translational deceleration, mm/s². */
  public void setTransDecel(double a) {
    motion.limits().setTransDecel(a);
  }

  /** The translational deceleration, mm/s². */
  public double getTransDecel() {
    return motion.limits().getTransDecel();
  }

  /** Rotational acceleration, deg/s². */
  public void setRotAccel(double a) {
    motion.limits().setRotAccel(a);
  }

  /** The rotational acceleration, deg/s². */
  public double getRotAccel() {
    return motion.limits().getRotAccel();
  }

  /** Rotational deceleration, deg/s². */
  public void setRotDecel(double a) {
    motion.limits().setRotDecel(a);
  }

  /** The rotational deceleration, deg/s². */
  public double getRotDecel() {
    return motion.limits().getRotDecel();
  }

  /** The top translational velocity this robot allows, mm/s (from CONFIGpac or parameters). */
  public double getAbsoluteMaxTransVel() {
    return motion.limits().getAbsoluteMaxTransVel();
  }

  /** Lowers (or raises) the top translational velocity. */
  public void setAbsoluteMaxTransVel(double mmPerSec) {
    motion.limits().setAbsoluteMaxTransVel(mmPerSec);
  }

  /** The top rotational velocity this robot allows, deg/s. */
  public double getAbsoluteMaxRotVel() {
    return motion.limits().getAbsoluteMaxRotVel();
  }

  /** Lowers (or raises) the top rotational velocity. */
  public void setAbsoluteMaxRotVel(double degPerSec) {
    motion.limits().setAbsoluteMaxRotVel(degPerSec);
  }

  // ---------------------------------------------------------------- direct commands

  /** Sends a command without argument now. */
  public boolean com(int command) {
    return sender.com(command);
  }

  /** Sends a command without argument now. */
  public boolean com(ArCommands command) {
    return sender.com(command.getNumber());
  }

  /** Sends a command with an integer argument now. */
  public boolean comInt(int command, int argument) {
    return sender.comInt(command, argument);
  }

  /** Sends a command with an integer argument now. */
  public boolean comInt(ArCommands command, int argument) {
    return sender.comInt(command.getNumber(), argument);
  }

  /** Sends a two-byte command (high, low) now. */
  public boolean com2Bytes(int command, int high, int low) {
    return sender.com2Bytes(command, high, low);
  }

  /** Sends a two-byte command (high, low) now. */
  public boolean com2Bytes(ArCommands command, int high, int low) {
    return sender.com2Bytes(command.getNumber(), high, low);
  }

  /** Sends a string command now. */
  public boolean comStr(int command, String argument) {
    return sender.comStr(command, argument);
  }

  /** Sends a string command now. */
  public boolean comStr(ArCommands command, String argument) {
    return sender.comStr(command.getNumber(), argument);
  }

  /**
   * Sends a string command with exactly {@code size} bytes now (ARIA's {@code comStrN}): the string
   * is cut or padded with NULs to {@code size}.
   */
  public boolean comStrN(int command, String argument, int size) {
    return sender.comStrN(command, argument, size);
  }

  /** Sends a string command with exactly {@code size} bytes now. */
  public boolean comStrN(ArCommands command, String argument, int size) {
    return sender.comStrN(command.getNumber(), argument, size);
  }

  /** Sends a command whose string argument is raw bytes (SAY's note pairs, TTY2 data). */
  public boolean comDataN(ArCommands command, byte[] data) {
    return sender.comDataN(command.getNumber(), data, 0, data.length);
  }

  /** Sends a packet you built and finalized yourself. */
  public boolean sendPacket(ArRobotPacket packet) {
    return sender.sendPacket(packet);
  }

  /** Turns the motors on (ENABLE 1). */
  public boolean enableMotors() {
    return sender.comInt(ArCommands.ENABLE.getNumber(), 1);
  }

  /** Turns the motors off (ENABLE 0). */
  public boolean disableMotors() {
    return sender.comInt(ArCommands.ENABLE.getNumber(), 0);
  }

  /** Turns all sonar arrays on. */
  public boolean enableSonar() {
    return sender.comInt(ArCommands.SONAR.getNumber(), 1);
  }

  /** Turns all sonar arrays off. */
  public boolean disableSonar() {
    return sender.comInt(ArCommands.SONAR.getNumber(), 0);
  }

  /** Asks for a continuous stream of ENCODERpacs. */
  public boolean requestEncoderPackets() {
    return sender.comInt(ArCommands.ENCODER.getNumber(), 2);
  }

  /** Stops the ENCODERpac stream. */
  public boolean stopEncoderPackets() {
    return sender.comInt(ArCommands.ENCODER.getNumber(), 0);
  }

  /** Asks for a continuous stream of IOpacs. */
  public boolean requestIOPackets() {
    return sender.comInt(ArCommands.IOREQUEST.getNumber(), 2);
  }

  /** Stops the IOpac stream. */
  public boolean stopIOPackets() {
    return sender.comInt(ArCommands.IOREQUEST.getNumber(), 0);
  }

  // ================================================================ pose transform

  /**
   * Declares that the robot is at {@code pose} now (ARIA's {@code moveTo}): odometry keeps
   * counting, but {@link #getPose()} and everything that uses it jump to the new pose. Range
   * devices' buffers move along.
   */
  public void moveTo(ArPose pose) {
    shiftRangeDevices(state.moveTo(pose));
  }

  /**
   * Sets the encoder→global transform so that odometry pose {@code encoderPose} corresponds to
   * global pose {@code globalPose} (what a localizer reports for an odometry pose it used).
   */
  public void setEncoderTransform(ArPose encoderPose, ArPose globalPose) {
    shiftRangeDevices(state.setEncoderTransform(encoderPose, globalPose));
  }

  private void shiftRangeDevices(ArTransform change) {
    for (ArRangeDevice d : rangeDevices) {
      d.applyTransform(change);
    }
  }

  /** The transform from odometry coordinates to global coordinates. */
  public ArTransform getEncoderTransform() {
    return state.status().encoderTransform();
  }

  /** The transform from the robot's local frame to global coordinates (at the current pose). */
  public ArTransform getToGlobalTransform() {
    return ArTransform.ofPose(getPose());
  }

  /** The transform from global coordinates to the robot's local frame. */
  public ArTransform getToLocalTransform() {
    return getToGlobalTransform().inverse();
  }

  // ================================================================ range devices

  /** Adds a range device (sonar, bumpers, laser ...) and tells it its robot. */
  public void addRangeDevice(ArRangeDevice device) {
    device.setRobot(this);
    rangeDevices.addIfAbsent(device);
  }

  /** Removes a range device. */
  public void remRangeDevice(ArRangeDevice device) {
    rangeDevices.remove(device);
  }

  /** The range device called {@code deviceName}, or null. */
  public ArRangeDevice findRangeDevice(String deviceName) {
    for (ArRangeDevice d : rangeDevices) {
      if (d.getName().equals(deviceName)) {
        return d;
      }
    }
    return null;
  }

  /** The range devices added to this robot. */
  public List<ArRangeDevice> getRangeDeviceList() {
    return List.copyOf(rangeDevices);
  }

  /**
   * The closest current reading of any range device in the sector from {@code startAngle}
   * counter-clockwise to {@code endAngle} (degrees, 0 ahead), in mm from the robot's centre; a
   * value of at least the devices' maximum range means nothing was seen.
   */
  public double checkRangeDevicesCurrentPolar(double startAngle, double endAngle) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.currentReadingPolar(startAngle, endAngle));
    }
    return best;
  }

  /** As {@link #checkRangeDevicesCurrentPolar}, over the cumulative buffers. */
  public double checkRangeDevicesCumulativePolar(double startAngle, double endAngle) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.cumulativeReadingPolar(startAngle, endAngle));
    }
    return best;
  }

  /**
   * The closest current reading of any range device inside the box with corners (x1, y1), (x2, y2)
   * in the robot's frame (x forward, y left, mm); a very large value if none.
   */
  public double checkRangeDevicesCurrentBox(double x1, double y1, double x2, double y2) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.currentReadingBox(x1, y1, x2, y2));
    }
    return best;
  }

  /** As {@link #checkRangeDevicesCurrentBox}, over the cumulative buffers. */
  public double checkRangeDevicesCumulativeBox(double x1, double y1, double x2, double y2) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.cumulativeReadingBox(x1, y1, x2, y2));
    }
    return best;
  }

  /**
   * Sets how each odometry heading change is corrected (ARIA's {@code
   * setEncoderCorrectionCallback}): a gyro replaces the wheels' turn with its own. Null removes the
   * correction. Called on the cycle thread for every SIP.
   */
  public void setEncoderCorrectionCallback(HeadingCorrection correction) {
    state.setHeadingCorrection(correction);
  }

  // ================================================================ actions

  /**
   * Adds an action with a priority (higher goes first; ARIA's examples use 1..100). The action is
   * told its robot. Adding the same action again only changes its priority.
   */
  public void addAction(ArAction action, int priority) {
    // Told its robot first, as in ARIA: an action without one is never fired.
    action.setRobot(this);
    actions.add(action, priority);
  }

  /** Removes an action. */
  public boolean remAction(ArAction action) {
    return actions.remove(action);
  }

  /** Removes the first action called {@code name}. */
  public boolean remAction(String name) {
    ArAction a = findAction(name);
    return a != null && remAction(a);
  }

  /** The action called {@code name}, or null. */
  public ArAction findAction(String name) {
    return actions.find(name);
  }

  /** The actions with their priorities, highest first. */
  public List<ArResolver.PrioritizedAction> getActionList() {
    return actions.list();
  }

  /** Deactivates every action. */
  public void deactivateActions() {
    actions.deactivateAll();
  }

  /** Replaces the resolver (the default is an {@link ArPriorityResolver}). */
  public void setResolver(ArResolver r) {
    actions.setResolver(r);
  }

  /** The resolver. */
  public ArResolver getResolver() {
    return actions.resolver();
  }

  /** The actions' combined desire in the last cycle (a copy). */
  public ArActionDesired getActionDesired() {
    return actions.desiredCopy();
  }

  // ================================================================ shutdown

  /**
   * Disconnects (sending CLOSE), stops the cycle and waits for its thread to end. Safe to call more
   * than once.
   */
  @Override
  public void close() {
    if (isConnected()) {
      disconnect();
    }
    stopRunning();
    try {
      waitForRunExit();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    ArDeviceConnection c = getDeviceConnection();
    if (c != null) {
      c.close();
    }
  }

  /** Counts of internal events for diagnostics: skipped cycles, overruns. */
  public String getDiagnostics() {
    return String.format(
        java.util.Locale.ROOT,
        "%s: counter %d, last cycle %.2f ms, lock waits %d, overruns %d, %s",
        name,
        counter.get(),
        lastCycleNanos / 1e6,
        lockWarnings.get(),
        overrunWarnings.get(),
        getDropCounters());
  }
}
