package org.jaria.arnl;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.IntConsumer;
import org.jaria.arnl.mcl.PoseEstimate;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigException;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.range.ArRangeDevice;
import org.jaria.robot.ArRobot;

/**
 * What laser and sonar localization share (ARNL's {@code ArBaseLocalizationTask}): Monte Carlo
 * localization that keeps the robot's pose on a map from odometry and a range sensor, and corrects
 * {@link ArRobot#getPose()} through the encoder→global transform, so that everything using the
 * robot's pose (path planning, goto actions, drawings) sees the localized pose. {@link
 * ArSonarLocalizationTask} feeds it the sonar ring, {@link ArLocalizationTask} a laser; the filter,
 * the state machine, the thread and this API are the same.
 *
 * <p><b>How it runs.</b> A cheap sensor-interpretation task on the robot's cycle notes new readings
 * and, once the robot has moved {@code TriggerDistance} mm or turned {@code TriggerAngle} degrees
 * since the last update, hands the odometry pose and the readings to the filter. In {@link
 * UpdateMode#THREADED} mode (the default, for real robots) the filter runs on its own thread, so
 * the cycle never waits for it; in {@link UpdateMode#SYNCHRONOUS} mode it runs inside that task,
 * which is what lockstep simulations and benchmarks need. Both compute exactly the same estimates
 * from the same inputs.
 *
 * <p><b>Thread safety.</b> Every public method may be called from any thread. Callbacks run on the
 * thread that did the update and must return quickly.
 */
public abstract class ArBaseLocalizationTask implements AutoCloseable {

  /** Where updates run. */
  public enum UpdateMode {
    /** On the task's own thread (real robots). */
    THREADED,
    /** Inside the robot's cycle (lockstep simulation, benchmarks). */
    SYNCHRONOUS
  }

  private final ArRobot robot;
  private final ArMap map;
  private final LocalizationParams params;
  private final UpdateMode mode;
  private final LocalizationCore core;
  private final UpdateFeeder feeder;
  private final String taskName;
  final CopyOnWriteArrayList<Runnable> stateChangeCBs = new CopyOnWriteArrayList<>();
  final CopyOnWriteArrayList<IntConsumer> failedCBs = new CopyOnWriteArrayList<>();
  final CopyOnWriteArrayList<Runnable> lostCBs = new CopyOnWriteArrayList<>();
  private volatile boolean idle;
  private volatile ArPose home = ArPose.ORIGIN;

  /**
   * The task for {@code robot} on {@code map}, reading its sensor through {@code feed} (made from
   * the parameters), registered on the robot's cycle and, if threaded, with its thread started.
   */
  ArBaseLocalizationTask(
      BaseBuilder<?> b,
      LocalizationParams params,
      java.util.function.Function<LocalizationParams, ScanFeed> feed) {
    this.robot = Objects.requireNonNull(b.robot, "robot");
    this.map = Objects.requireNonNull(b.map, "map");
    this.params = params;
    this.mode = b.mode;
    ScanFeed f = feed.apply(params);
    this.core = new LocalizationCore(this, robot, map, params, b.seed, f);
    this.taskName = b.name;
    this.feeder =
        new UpdateFeeder(robot, params, mode, taskName + "-" + robot.getName(), f, core::process);
    robot.addSensorInterpTask(
        taskName, 40, () -> feeder.sensorInterp(core.initialized() && !idle, core.generation()));
  }

  /** The options every localization task takes; each task's builder adds its sensor. */
  public abstract static class BaseBuilder<B extends BaseBuilder<B>> {
    final ArRobot robot;
    final ArMap map;
    ArConfig config;
    UpdateMode mode = UpdateMode.THREADED;
    long seed = 1;
    String name;

    BaseBuilder(ArRobot robot, ArMap map, String defaultName) {
      this.robot = robot;
      this.map = map;
      this.name = defaultName;
    }

    abstract B self();

    /** Registers the parameters in {@code c} (default: a config of the task's own). */
    public B config(ArConfig c) {
      config = c;
      return self();
    }

    /** Threaded (default) or synchronous updates. */
    public B mode(UpdateMode m) {
      mode = Objects.requireNonNull(m, "mode");
      return self();
    }

    /** Seed of the filter's random numbers (default 1). */
    public B seed(long s) {
      seed = s;
      return self();
    }

    /** Name of the sensor-interpretation task and thread. */
    public B name(String n) {
      name = Objects.requireNonNull(n, "name");
      return self();
    }

    /**
     * Refuses a sensor that was added to another robot: its readings would be that robot's.
     *
     * @throws IllegalArgumentException naming both robots
     */
    void requireThisRobots(ArRangeDevice device, String kind) {
      if (device.getRobot() != null && device.getRobot() != robot) {
        throw new IllegalArgumentException(
            "the "
                + kind
                + " '"
                + device.getName()
                + "' belongs to robot '"
                + device.getRobot().getName()
                + "': pass the "
                + kind
                + " added to the robot being localized");
      }
    }

    /** The config to register the parameters in: the one given, or a new one. */
    ArConfig configOrNew() {
      return config == null ? new ArConfig() : config;
    }
  }

  // ================================================================ cycle side

  /**
   * Waits until every update handed to the localization thread so far has been done (at once in
   * synchronous mode). Useful before reading the estimate after driving, and in tests.
   *
   * @param timeoutMs longest wait, real milliseconds
   * @return whether the thread caught up in time
   */
  public boolean awaitIdle(long timeoutMs) throws InterruptedException {
    return feeder.awaitIdle(timeoutMs);
  }

  // ================================================================ initial localization

  /**
   * Tries every home position of the map (RobotHome objects, else Docks, else the origin) and the
   * robot's current pose, with the configured spreads ({@code StdX}, {@code StdY}, {@code StdTh});
   * the one where the current readings fit the map best becomes the robot's pose and its home.
   * Needs readings: connect and let the robot run a moment first.
   *
   * @return whether the best candidate passed the {@code PassThreshold}
   */
  public boolean localizeRobotAtHomeBlocking() {
    return localizeRobotAtHomeBlocking(
        params.stdX.getDouble(), params.stdY.getDouble(), params.stdTh.getDouble());
  }

  /** As {@link #localizeRobotAtHomeBlocking()}, with the given spreads (mm, mm, degrees). */
  public boolean localizeRobotAtHomeBlocking(double spreadX, double spreadY, double angleSpread) {
    List<ArPose> candidates = new ArrayList<>();
    for (ArMapObject o : map.getMapObjects()) {
      if (o.type().equalsIgnoreCase("RobotHome")) {
        candidates.add(o.pose());
      }
    }
    if (candidates.isEmpty()) {
      for (ArMapObject o : map.getMapObjects()) {
        if (o.type().equalsIgnoreCase("Dock")) {
          candidates.add(o.pose());
        }
      }
    }
    if (candidates.isEmpty()) {
      candidates.add(ArPose.ORIGIN);
    }
    if (core.initialized()) {
      candidates.add(robot.getPose());
    }
    boolean ok =
        core.localizeAmong(
            candidates, params.numSamplesAtInit.getInt(), spreadX, spreadY, angleSpread);
    home = robot.getPose();
    return ok;
  }

  /**
   * Localizes at a given pose with the configured spreads (ARNL's {@code localizeRobotInMapInit}).
   *
   * @return whether the result passed the {@code PassThreshold}
   */
  public boolean localizeRobotAtPose(ArPose pose) {
    return localizeRobotAtPose(
        pose, params.stdX.getDouble(), params.stdY.getDouble(), params.stdTh.getDouble());
  }

  /** Localizes at a given pose with the given spreads (mm, mm, degrees). */
  public boolean localizeRobotAtPose(ArPose pose, double stdX, double stdY, double stdTh) {
    return core.localizeAmong(List.of(pose), params.numSamplesAtInit.getInt(), stdX, stdY, stdTh);
  }

  /**
   * ARNL's name for {@link #localizeRobotAtPose(ArPose, double, double, double)}: particles spread
   * around {@code given}, weighed against the current readings; the result becomes the robot's
   * pose.
   *
   * @return whether the result passed the {@code PassThreshold}
   */
  public boolean localizeRobotInMapInit(ArPose given, double stdX, double stdY, double stdTh) {
    return localizeRobotAtPose(given, stdX, stdY, stdTh);
  }

  /**
   * ARNL's {@code setRobotPose}: the robot is at {@code pose} give or take {@code spread} (x, y mm
   * and th degrees, as standard deviations; zeros for the configured {@code StdX/StdY/StdTh}). The
   * pose is checked against the readings as by {@link #localizeRobotAtPose}.
   *
   * @return whether the result passed the {@code PassThreshold}
   */
  public boolean setRobotPose(ArPose pose, ArPose spread) {
    boolean none = spread.x() == 0 && spread.y() == 0 && spread.th() == 0;
    return none
        ? localizeRobotAtPose(pose)
        : localizeRobotAtPose(pose, spread.x(), spread.y(), spread.th());
  }

  /**
   * Sets the robot's pose at once and restarts tracking from a particle cloud around it (ARNL's
   * {@code forceUpdatePose}), with the configured number of particles and spreads.
   */
  public void forceUpdatePose(ArPose pose) {
    forceUpdatePose(
        pose,
        params.numSamples.getInt(),
        params.stdX.getDouble(),
        params.stdY.getDouble(),
        params.stdTh.getDouble());
  }

  /**
   * Sets the robot's pose at once and restarts tracking from {@code numSamples} particles spread
   * around it (mm, mm, degrees).
   */
  public void forceUpdatePose(ArPose pose, int numSamples, double xStd, double yStd, double thStd) {
    core.forceUpdatePose(pose, numSamples, xStd, yStd, thStd);
  }

  /**
   * Forgets the pose and searches the whole free space of the map ({@code GlobalNumSamples}
   * particles). The first update with a few echoes places the particles where that scan fits the
   * map (a grid of poses over the free space is weighed with the sensor model: up to a second on a
   * large map, once), so that every place that looks like where the robot is gets its share. The
   * robot should drive meanwhile; the state is {@link
   * LocalizationState#LOCALIZATION_INIT_COMPUTING} until one place has kept most of the particles
   * for ten updates, then the pose is corrected as in normal tracking. In a building of identical
   * rooms that takes until the robot sees something that tells them apart.
   */
  public void startGlobalLocalization() {
    core.startGlobalLocalization();
  }

  // ================================================================ state

  /** Share (0..1) of the last update's echoes that the map explains (ARNL's score). */
  public double getLocalizationScore() {
    return core.score();
  }

  /** The score an update needs to pass (ARNL's localization threshold; {@code PassThreshold}). */
  public double getLocalizationThreshold() {
    return params.getPassThreshold();
  }

  /** Sets the score an update needs to pass, 0..1. */
  public void setLocalizationThreshold(double t) {
    params.setPassThreshold(t);
  }

  /**
   * Whether the robot counts as localized: initialized, and the last updates passed (ARNL's {@code
   * getRobotIsLocalized}; false while lost, after a failed update and during a global search).
   */
  public boolean getRobotIsLocalized() {
    return core.initialized() && core.lockState() == LockState.LOCKED;
  }

  /** Whether updates are switched off ({@link #setIdleFlag}). */
  public boolean getIdleFlag() {
    return idle;
  }

  /** Particles in use now. */
  public int getCurrentNumSamples() {
    return core.currentNumSamples();
  }

  /** Particles used while tracking ({@code NumSamples}). */
  public int getNumSamples() {
    return params.getNumSamples();
  }

  /** What the task is doing. */
  public LocalizationState getState() {
    return idle ? LocalizationState.LOCALIZATION_IDLE : core.state();
  }

  /** How sure the task is. */
  public LockState getLockState() {
    return core.lockState();
  }

  /** Whether the robot is lost (many failed updates in a row). */
  public boolean getRobotIsLostFlag() {
    return core.lockState() == LockState.LOST;
  }

  /** Updates in a row that failed the {@code PassThreshold} (0 after a passing one). */
  public int getFailedUpdateCount() {
    return core.failedUpdates();
  }

  /** Whether an initial pose has been set. */
  public boolean getInitializedFlag() {
    return core.initialized();
  }

  /** The pose found by the last {@link #localizeRobotAtHomeBlocking()}. */
  public ArPose getRobotHome() {
    return home;
  }

  /** The filter's latest estimate (pose and spread), or null before the first. */
  public PoseEstimate getEstimate() {
    return core.estimate();
  }

  /** The latest localized pose (ARNL's {@code getCurrentLocaPose}). */
  public ArPose getCurrentLocaPose() {
    PoseEstimate e = core.estimate();
    return e == null ? robot.getPose() : e.pose();
  }

  /** The particles (a copy, for display). */
  public List<ArPose> getCurrentSamplePoses() {
    return core.samples();
  }

  /** Updates done so far. */
  public long getUpdateCount() {
    return core.updates();
  }

  /** Updates skipped because the thread fell behind (threaded mode). */
  public long getDroppedUpdateCount() {
    return feeder.droppedCount();
  }

  /** Stops (true) or restarts (false) updates; the pose then follows odometry alone. */
  public void setIdleFlag(boolean f) {
    idle = f;
  }

  /** The update mode. */
  public UpdateMode getUpdateMode() {
    return mode;
  }

  /** The parameters. */
  public LocalizationParams getParams() {
    return params;
  }

  /** The config holding the parameters. */
  public ArConfig getConfig() {
    return params.getConfig();
  }

  /**
   * Loads parameters from an ARNL-style file ({@code Section Localization} ...).
   *
   * @throws ArConfigException naming file and line if a value is bad (nothing is applied)
   */
  public ArConfig.ParseResult loadParamFile(Path file) throws ArConfigException, IOException {
    return params.getConfig().parseFile(file);
  }

  /** The map. */
  public ArMap getMap() {
    return map;
  }

  /** The cycle-side feeder (for the core). */
  UpdateFeeder feeder() {
    return feeder;
  }

  /** The robot. */
  public ArRobot getRobot() {
    return robot;
  }

  // ================================================================ callbacks

  /** Runs when the state or lock state changes. */
  public void addStateChangeCB(Runnable cb) {
    stateChangeCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a state-change callback. */
  public void remStateChangeCB(Runnable cb) {
    stateChangeCBs.remove(cb);
  }

  /** Runs after every failed update, with the number of failures in a row. */
  public void addFailedLocalizationCB(IntConsumer cb) {
    failedCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a failed-localization callback. */
  public void remFailedLocalizationCB(IntConsumer cb) {
    failedCBs.remove(cb);
  }

  /** Runs when the robot becomes lost. */
  public void addLostCB(Runnable cb) {
    lostCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a lost callback. */
  public void remLostCB(Runnable cb) {
    lostCBs.remove(cb);
  }

  // ================================================================ shutdown

  /** Removes the task from the robot and stops and joins its thread. Safe to call twice. */
  @Override
  public void close() {
    robot.remSensorInterpTask(taskName);
    feeder.stop();
  }
}
