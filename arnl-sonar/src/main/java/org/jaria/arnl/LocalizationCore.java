package org.jaria.arnl;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.IntConsumer;
import org.jaria.arnl.mcl.PoseEstimate;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The state machine behind a localization task ({@link ArBaseLocalizationTask}): runs the filter
 * ({@link LocalizationEngine}) under one lock for updates and (re)initializations, judges each
 * update against the pass threshold, counts failures towards "lost", follows a global search until
 * it has really converged, corrects the robot's pose, and collects the callbacks to run once the
 * lock is released. Published state is readable from any thread.
 */
final class LocalizationCore {

  private static final Logger log = LoggerFactory.getLogger(ArBaseLocalizationTask.class);

  /** Passing updates in a row a lost robot needs before it counts as localized again. */
  private static final int RELOCK_PASSES = 3;

  /** Updates in a row the global search must look converged before it is believed. */
  private static final int GLOBAL_STREAK = 10;

  /** Share of the weight the best cluster must hold for a global search to count as converged. */
  private static final double GLOBAL_CLUSTER = 0.8;

  private final ArBaseLocalizationTask task;
  private final ScanFeed feed;
  private final ArRobot robot;
  private final LocalizationParams params;
  private final ReentrantLock lock = new ReentrantLock();

  // The filter is not thread-safe: only this field's lock keeps its users apart.
  @GuardedBy("lock")
  private final LocalizationEngine engine;

  // Changed under the lock; an AtomicLong because the cycle also reads it without the lock.
  private final AtomicLong generation = new AtomicLong();

  @GuardedBy("lock")
  private int consecutiveFailures;

  @GuardedBy("lock")
  private int consecutivePasses;

  @GuardedBy("lock")
  private boolean global;

  @GuardedBy("lock")
  private int globalStreak;

  // Published: written under the lock, read by any thread without it.
  private volatile boolean initialized;
  private volatile LocalizationState state = LocalizationState.NOT_INITIALIZED;
  private volatile LockState lockState = LockState.LOCK_NOT_INITIALIZED;
  private volatile double score;
  private volatile int failedUpdates;
  private volatile int currentNumSamples;
  private volatile PoseEstimate estimate;
  private final AtomicLong updates = new AtomicLong();

  LocalizationCore(
      ArBaseLocalizationTask task,
      ArRobot robot,
      ArMap map,
      LocalizationParams params,
      long seed,
      ScanFeed feed) {
    this.task = task;
    this.feed = feed;
    this.robot = robot;
    this.params = params;
    this.engine =
        new LocalizationEngine(map, params, robot.getRobotParams().getRobotRadius(), seed);
  }

  /** One filter update; then the pose correction and the callbacks. */
  void process(UpdateFeeder.Input in) {
    List<Runnable> notify = new ArrayList<>();
    lock.lock();
    try {
      if (in.generation() != generation.get() || !engine.hasParticles()) {
        return;
      }
      LocalizationEngine.Result r = engine.update(in.encoderPose(), in.scan(), isLost(), global);
      updates.incrementAndGet();
      estimate = r.estimate();
      currentNumSamples = r.numSamples();
      LocalizationState oldState = state;
      LockState oldLock = lockState;
      if (global) {
        boolean converged =
            r.estimate().isConverged(300, 10, GLOBAL_CLUSTER)
                && r.score() >= params.passThreshold.getDouble();
        globalStreak = converged ? globalStreak + 1 : 0;
        // One good-looking update is not enough: in a corridor a mirrored pose fits for a while.
        if (globalStreak >= GLOBAL_STREAK) {
          global = false;
          engine.shrinkTo(params.numSamples.getInt());
          currentNumSamples = engine.numSamples();
          consecutiveFailures = 0;
          state = LocalizationState.LOCALIZATION_SUCCESS;
          lockState = LockState.LOCKED;
          log.info("global localization converged at {}", r.estimate().pose());
        }
      } else if (r.echoes() >= params.minEchoes.getInt()) {
        judge(r.score(), notify);
      }
      if (r.score() >= 0) {
        score = r.score();
      }
      if (!global && lockState != LockState.LOST) {
        robot.setEncoderTransform(in.encoderPose(), r.estimate().pose());
      }
      failedUpdates = consecutiveFailures;
      if (state != oldState || lockState != oldLock) {
        notify.addAll(task.stateChangeCBs);
      }
    } finally {
      lock.unlock();
    }
    runAll(notify);
  }

  /** Passes or fails an update by its score; counts failures towards "lost". */
  @GuardedBy("lock")
  private void judge(double s, List<Runnable> notify) {
    if (s >= params.passThreshold.getDouble()) {
      consecutiveFailures = 0;
      consecutivePasses++;
      state = LocalizationState.LOCALIZATION_SUCCESS;
      // A lost robot's recovery particles fit somewhere by chance now and then: one good update
      // is not enough to trust the pose again.
      if (lockState != LockState.LOST || consecutivePasses >= RELOCK_PASSES) {
        if (lockState == LockState.LOST) {
          log.info("localization recovered at {}", estimate == null ? "?" : estimate.pose());
        }
        lockState = LockState.LOCKED;
      }
      return;
    }
    consecutivePasses = 0;
    consecutiveFailures++;
    state = LocalizationState.LOCALIZATION_FAILED;
    int fails = consecutiveFailures;
    for (IntConsumer cb : task.failedCBs) {
      notify.add(() -> cb.accept(fails));
    }
    if (consecutiveFailures >= params.failuresToLost.getInt()) {
      if (lockState != LockState.LOST) {
        log.warn("localization lost after {} failed updates", consecutiveFailures);
        notify.addAll(task.lostCBs);
      }
      lockState = LockState.LOST;
    } else {
      lockState = LockState.LOST_LOCK;
    }
  }

  private boolean isLost() {
    return lockState == LockState.LOST;
  }

  private static void runAll(List<Runnable> cbs) {
    for (Runnable r : cbs) {
      try {
        r.run();
      } catch (RuntimeException e) {
        log.error("localization callback threw", e);
      }
    }
  }

  boolean localizeAmong(List<ArPose> candidates, int numSamples, double sx, double sy, double sth) {
    ArPose enc = robot.getEncoderPose();
    SonarScan scan = feed.current(enc);
    if (task.getUpdateMode() == ArBaseLocalizationTask.UpdateMode.THREADED) {
      // Right after connecting the sensor may not have reported yet: give it up to two seconds
      // (the robot's cycle runs on its own thread, so waiting here lets readings arrive).
      long deadline = robot.getClock().nanoTime() + TimeUnit.SECONDS.toNanos(2);
      while (scan.size() < 4 && robot.getClock().nanoTime() < deadline) {
        try {
          robot.getClock().sleepMillis(100);
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
          break;
        }
        enc = robot.getEncoderPose();
        scan = feed.current(enc);
      }
    }
    boolean pass;
    List<Runnable> notify = new ArrayList<>();
    lock.lock();
    try {
      LocalizationState old = state;
      generation.incrementAndGet();
      global = false;
      LocalizationEngine.Result r =
          engine.localizeAt(candidates, enc, scan, numSamples, sx, sy, sth);
      estimate = r.estimate();
      currentNumSamples = engine.numSamples();
      pass = r.score() >= params.passThreshold.getDouble();
      if (r.echoes() == 0) {
        log.warn(
            "no {} to localize with: connect and run the robot a moment first;"
                + " using {} as it is",
            feed.what(),
            r.estimate().pose());
      }
      score = Math.max(0, r.score());
      consecutiveFailures = pass ? 0 : 1;
      failedUpdates = consecutiveFailures;
      state = pass ? LocalizationState.LOCALIZATION_SUCCESS : LocalizationState.LOCALIZATION_FAILED;
      lockState = pass ? LockState.LOCKED : LockState.LOST_LOCK;
      robot.setEncoderTransform(enc, r.estimate().pose());
      startTracking(enc);
      if (old != state) {
        notify.addAll(task.stateChangeCBs);
      }
    } finally {
      lock.unlock();
    }
    runAll(notify);
    return pass;
  }

  /** Called under the lock after a (re)initialization: tracking restarts from here. */
  @GuardedBy("lock")
  private void startTracking(ArPose enc) {
    initialized = true;
    task.feeder().restartFrom(enc);
  }

  /**
   * Sets the robot's pose at once and restarts tracking from {@code numSamples} particles spread
   * around it (mm, mm, degrees).
   */
  void forceUpdatePose(ArPose pose, int numSamples, double xStd, double yStd, double thStd) {
    ArPose enc = robot.getEncoderPose();
    List<Runnable> notify = new ArrayList<>();
    lock.lock();
    try {
      generation.incrementAndGet();
      global = false;
      engine.reset(pose, enc, numSamples, xStd, yStd, thStd);
      currentNumSamples = engine.numSamples();
      estimate = new PoseEstimate(pose, xStd, yStd, thStd, 1);
      consecutiveFailures = 0;
      failedUpdates = 0;
      LockState old = lockState;
      state = LocalizationState.LOCALIZATION_SUCCESS;
      lockState = LockState.LOCKED;
      robot.setEncoderTransform(enc, pose);
      startTracking(enc);
      if (old != lockState) {
        notify.addAll(task.stateChangeCBs);
      }
    } finally {
      lock.unlock();
    }
    runAll(notify);
  }

  /**
   * Forgets the pose and searches the whole free space of the map ({@code GlobalNumSamples}
   * particles). The robot should drive meanwhile; the state is {@link
   * LocalizationState#LOCALIZATION_INIT_COMPUTING} until the particles have gathered, then the pose
   * is corrected as in normal tracking.
   */
  void startGlobalLocalization() {
    ArPose enc = robot.getEncoderPose();
    lock.lock();
    try {
      generation.incrementAndGet();
      global = true;
      globalStreak = 0;
      engine.startGlobal(enc, params.globalNumSamples.getInt());
      currentNumSamples = engine.numSamples();
      consecutiveFailures = 0;
      failedUpdates = 0;
      state = LocalizationState.LOCALIZATION_INIT_COMPUTING;
      lockState = LockState.LOST_LOCK;
      startTracking(enc);
    } finally {
      lock.unlock();
    }
    runAll(new ArrayList<>(task.stateChangeCBs));
  }

  long generation() {
    return generation.get();
  }

  boolean initialized() {
    return initialized;
  }

  LocalizationState state() {
    return state;
  }

  LockState lockState() {
    return lockState;
  }

  double score() {
    return score;
  }

  int failedUpdates() {
    return failedUpdates;
  }

  int currentNumSamples() {
    return currentNumSamples;
  }

  PoseEstimate estimate() {
    return estimate;
  }

  long updates() {
    return updates.get();
  }

  /** The particles as poses (a copy). */
  List<ArPose> samples() {
    lock.lock();
    try {
      return engine.samples();
    } finally {
      lock.unlock();
    }
  }
}
