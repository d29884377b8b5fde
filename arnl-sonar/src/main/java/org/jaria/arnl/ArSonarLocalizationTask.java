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
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/**
 * Sonar Monte Carlo localization (SonARNL's {@code ArSonarLocalizationTask}): keeps the robot's
 * pose on a line map using odometry and the sonar ring, and corrects {@link ArRobot#getPose()}
 * through the encoder→global transform, so that everything using the robot's pose (path planning,
 * goto actions, drawings) sees the localized pose.
 *
 * <pre>{@code
 * ArSonarLocalizationTask loc = new ArSonarLocalizationTask(robot, sonar, map); // own thread
 * loc.localizeRobotAtHomeBlocking();
 * ...
 * double score = loc.getLocalizationScore();
 * }</pre>
 *
 * <p><b>How it runs.</b> A cheap sensor-interpretation task on the robot's cycle notes new sonar
 * readings and, once the robot has moved {@code TriggerDistance} mm or turned {@code TriggerAngle}
 * degrees since the last update (200 mm and 5° by default, as in the thesis), hands the odometry
 * pose and the readings to the filter. In {@link UpdateMode#THREADED} mode (the default, for real
 * robots) the filter runs on its own thread, so the cycle never waits for it; in {@link
 * UpdateMode#SYNCHRONOUS} mode it runs inside that task, which is what lockstep simulations and
 * benchmarks need. Both compute exactly the same estimates from the same inputs.
 *
 * <p><b>Thread safety.</b> Every public method may be called from any thread. Callbacks run on the
 * thread that did the update and must return quickly.
 */
public final class ArSonarLocalizationTask implements AutoCloseable {

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
   * ARNL's constructor: localization on its own thread, default parameters in a config of its own,
   * seed 1.
   */
  public ArSonarLocalizationTask(ArRobot robot, ArSonarDevice sonar, ArMap map) {
    this(builder(robot, map).sonar(sonar));
  }

  private ArSonarLocalizationTask(Builder b) {
    this.robot = Objects.requireNonNull(b.robot, "robot");
    this.map = Objects.requireNonNull(b.map, "map");
    this.params = new LocalizationParams(b.config == null ? new ArConfig() : b.config);
    this.mode = b.mode;
    this.core = new LocalizationCore(this, robot, map, params, b.seed);
    this.taskName = b.name;
    this.feeder =
        new UpdateFeeder(robot, params, mode, taskName + "-" + robot.getName(), core::process);
    robot.addSensorInterpTask(
        taskName, 40, () -> feeder.sensorInterp(core.initialized() && !idle, core.generation()));
  }

  /** A builder for the task with more options than ARNL's constructor. */
  public static Builder builder(ArRobot robot, ArMap map) {
    return new Builder(robot, map);
  }

  /** Options for {@link ArSonarLocalizationTask}. */
  public static final class Builder {
    private final ArRobot robot;
    private final ArMap map;
    private ArConfig config;
    private UpdateMode mode = UpdateMode.THREADED;
    private long seed = 1;
    private String name = "sonarLocalization";

    private Builder(ArRobot robot, ArMap map) {
      this.robot = robot;
      this.map = map;
    }

    /**
     * The sonar whose echoes localize the robot: the sonar ring of this robot. The filter reads the
     * ring's echoes from the robot's SIPs, where the device takes them too, so the device must not
     * belong to another robot.
     *
     * @throws NullPointerException if {@code sonar} is null: sonar localization needs the sonar
     * @throws IllegalArgumentException if {@code sonar} was added to another robot
     */
    public Builder sonar(ArSonarDevice sonar) {
      Objects.requireNonNull(
          sonar, "sonar: sonar localization needs the robot's ArSonarDevice, not null");
      if (sonar.getRobot() != null && sonar.getRobot() != robot) {
        throw new IllegalArgumentException(
            "the sonar '"
                + sonar.getName()
                + "' belongs to robot '"
                + sonar.getRobot().getName()
                + "': pass the sonar added to the robot being localized");
      }
      return this;
    }

    /** Registers the parameters in {@code c} (default: a config of the task's own). */
    public Builder config(ArConfig c) {
      config = c;
      return this;
    }

    /** Threaded (default) or synchronous updates. */
    public Builder mode(UpdateMode m) {
      mode = Objects.requireNonNull(m, "mode");
      return this;
    }

    /** Seed of the filter's random numbers (default 1). */
    public Builder seed(long s) {
      seed = s;
      return this;
    }

    /** Name of the sensor-interpretation task and thread (default "sonarLocalization"). */
    public Builder name(String n) {
      name = Objects.requireNonNull(n, "name");
      return this;
    }

    /** Creates the task, registers it on the robot and, if threaded, starts its thread. */
    public ArSonarLocalizationTask build() {
      return new ArSonarLocalizationTask(this);
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
   * the one where the current sonar readings fit the map best becomes the robot's pose and its
   * home. Needs sonar readings: connect and let the robot run a moment first.
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
