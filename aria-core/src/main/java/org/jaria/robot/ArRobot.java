package org.jaria.robot;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArPriorityResolver;
import org.jaria.action.ArResolver;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
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
 *
 * <p><b>Inside.</b> This class is the ARIA-style facade; the work is done by stages that each own
 * their state and pass data one way: {@code RobotLink} (connection, packet queue, handshake,
 * timeouts) hands packets to {@code PacketRouter} (the packet handlers), whose SIP handler in
 * {@code StatusStage} turns them through {@code SipProcessor} into the {@link RobotStatus} the
 * getters read. Going out, {@code ActionStage} resolves the actions' desires, {@code
 * StateReflection} decides the motion commands of the cycle, and {@code StateReflector} sends them
 * through the one {@link ArRobotPacketSender}.
 *
 * <p><b>Where the methods are.</b> ARIA's {@code ArRobot} has about 200 methods. This class keeps
 * the ones that tie the stages together (the constructors, {@link #loopOnce()}, range devices, the
 * encoder transform, actions, {@link #close()}); the rest are grouped by job in the interfaces it
 * implements, one file each: {@link ConnectionLifecycle} (connecting, callbacks), {@link
 * RobotCycle} (running the cycle, tasks, packet handlers, the lock), {@link RobotReadings} (what
 * the last SIP said, sonar, size), {@link MotionCommands} (motion commands and limits) and {@link
 * RobotCommands} (direct commands). They are all methods of {@code ArRobot}, as in ARIA.
 */
public non-sealed class ArRobot
    implements AutoCloseable,
        ConnectionLifecycle,
        RobotCycle,
        RobotReadings,
        MotionCommands,
        RobotCommands {

  private static final Logger log = LoggerFactory.getLogger(ArRobot.class);

  /** The clock every wait and timeout of this robot uses. */
  protected final Clock clock;

  private final String name;
  private final DropCounters drops;
  private final StatusStage state;
  final ArRobotPacketSender sender;
  final StateReflector motion;
  private final ActionStage actions = new ActionStage();
  private final CopyOnWriteArrayList<ArRangeDevice> rangeDevices = new CopyOnWriteArrayList<>();
  final CycleParts cycle;

  /** The run-exit callbacks, which the run loop calls (the cycle's own list). */
  final Callbacks runExitCBs;

  final RobotLink link;

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
    this.cycle = new CycleParts(new RunLoop(this));
    this.runExitCBs = cycle.runExitCBs;
    this.link =
        new RobotLink(
            clock,
            sender,
            drops,
            cycle.router,
            cycle.robotLock,
            this::getCycleTime,
            cycle.runLoop::isRunning,
            new LinkEvents());
    motion.setDoStateReflection(doStateReflection);
    cycle.router.add(p -> state.handleSip(p, cycle.counter()), ArListPos.LAST);
    cycle.router.add(state::handleEncoderPacket, ArListPos.LAST);
    cycle.router.add(state::handleIoPacket, ArListPos.LAST);
  }

  /** What the robot does when its link changes. */
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
    public void configured(ArConfigPacket config, ArRobotParams p) {
      LimitsFromConfig.apply(ArRobot.this, config, p);
    }
  }

  /** The robot's name as given to the constructor. */
  public String getName() {
    return name;
  }

  // ================================================================ the cycle (see RobotCycle)

  /**
   * Runs one cycle now: reads what has arrived (without waiting), then packet handlers, sensor
   * interpretation, actions, state reflection and user tasks. While a connection is being made it
   * advances the handshake instead.
   */
  public void loopOnce() {
    long start = clock.nanoTime();
    long realStart = System.nanoTime();
    if (link.stepConnecting(start)) {
      cycle.countCycle();
      return;
    }
    if (isConnected()) {
      link.readAvailable(start);
    }
    boolean locked;
    try {
      locked = cycle.robotLock.tryLock(Math.max(1, cycle.cycleTimeMs()), TimeUnit.MILLISECONDS);
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
      cycle.sensorInterpTasks.runAll();
      ArActionDesired desired = actions.resolve(this, isConnected());
      if (isConnected()) {
        motion.reflect(desired, state.encoderTransform().getTh());
      }
      cycle.userTasks.runAll();
    } finally {
      cycle.robotLock.unlock();
    }
    cycle.countCycle();
    cycle.setLastCycleNanos(System.nanoTime() - realStart);
    // Measured on the robot's clock, like every other time in the robot: on a virtual clock a
    // cycle takes no time unless a task makes time pass, so runs stay deterministic.
    long took = clock.nanoTime() - start;
    long overrun = cycle.countIfOverrun(took);
    if (overrun > 0) {
      warnRarely(
          overrun,
          "cycle took {} ms, more than the {} ms warning time: a task is too slow",
          TimeUnit.NANOSECONDS.toMillis(took),
          cycle.cycleWarningTimeMs());
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
        cycle.countSkipped(),
        "skipped a cycle: user code held the robot lock for more than {} ms (cycle time {} ms)",
        cycle.cycleTimeMs(),
        cycle.cycleTimeMs());
    if (isConnected() && now - sender.getLastSentNanos() > TimeUnit.MILLISECONDS.toNanos(500)) {
      sender.com(ArCommands.PULSE.getNumber());
    }
  }

  private static void warnRarely(long n, String format, Object a, Object b) {
    if (n == 1 || n % 100 == 0) {
      log.warn(format + " (#" + n + ")", a, b);
    }
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
  @Override
  public RobotStatus getStatus() {
    return state.status();
  }

  /** The parameters in use (from the robot's subtype and name once connected). */
  @Override
  public ArRobotParams getRobotParams() {
    return state.params();
  }

  /** The object that writes commands; its tap sees every packet sent. */
  @Override
  public ArRobotPacketSender getPacketSender() {
    return sender;
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
    return state.encoderTransform();
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
    actions.add(action, priority);
    action.setRobot(this);
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
        cycle.counter(),
        cycle.lastCycleNanos() / 1e6,
        cycle.skipped(),
        cycle.overruns(),
        getDropCounters());
  }
}
