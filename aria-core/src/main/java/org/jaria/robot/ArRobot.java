package org.jaria.robot;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.range.ArRangeDevice;
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
 */
public class ArRobot extends RobotDevices implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArRobot.class);

  private final String name;
  final ReentrantLock robotLock = new ReentrantLock();
  final TaskList sensorInterpTasks = new TaskList("sensor interpretation");
  final TaskList userTasks = new TaskList("user");
  private final PacketRouter router = new PacketRouter();
  final Callbacks runExitCBs = new Callbacks("run exit");
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
    super(clock, ArRobotParams.defaults(), new DropCounters(name));
    this.name = name;
    this.runLoop = new RunLoop(this);
    this.link =
        new RobotLink(
            clock,
            sender,
            getDropCounters(),
            router,
            robotLock,
            this::getCycleTime,
            runLoop::isRunning,
            new LinkEvents());
    motion.setDoStateReflection(doStateReflection);
    router.add(p -> handleSip(p, counter.get()), ArListPos.LAST);
    router.add(this::handleEncoderPacket, ArListPos.LAST);
    router.add(this::handleIoPacket, ArListPos.LAST);
  }

  /** What the robot does when its link changes. */
  private final class LinkEvents implements RobotLink.Events {
    @Override
    public void connecting() {
      resetState();
      motion.reset();
    }

    @Override
    public void identified(ArRobotParams p) {
      setParams(p);
      motion.configure(
          p.hasSettableVelMaxes(), p.hasSettableAccsDecs(), p.hasMoveCommand(), p.getVel2Divisor());
    }

    @Override
    public void configured(ArConfigPacket config, ArRobotParams p) {
      LimitsFromConfig.apply(ArRobot.this, config, p);
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
    return params;
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
      ArActionDesired desired = resolveActions(this, isConnected());
      if (isConnected()) {
        motion.reflect(desired, processor.getEncoderTransform().getTh());
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

  /** Adds a range device (sonar, bumpers, laser ...) and tells it its robot. */
  public void addRangeDevice(ArRangeDevice device) {
    device.setRobot(this);
    rangeDevices.addIfAbsent(device);
  }

  /**
   * Adds an action with a priority (higher goes first; ARIA's examples use 1..100). The action is
   * told its robot. Adding the same action again only changes its priority.
   */
  public void addAction(ArAction action, int priority) {
    insertAction(action, priority);
    action.setRobot(this);
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
