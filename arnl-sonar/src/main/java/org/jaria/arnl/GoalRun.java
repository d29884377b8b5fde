package org.jaria.arnl;

import java.util.Arrays;
import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArPose;

/**
 * What {@link ArPathPlanningTask} keeps about the goal in progress: the goal, the plan requests,
 * progress along the path, and obstacles remembered for replanning. Not thread-safe and without a
 * lock of its own: {@link GoalKeeper} keeps the one instance in a field {@code @GuardedBy} its lock
 * (so Error Prone checks every reach for it there), and hands it to {@link PathFollower} only
 * inside {@link GoalKeeper#fire}, with that lock held.
 */
final class GoalRun {

  /** Remembered obstacle points are forgotten after this long. */
  private static final long STAMP_LIFE = TimeUnit.SECONDS.toNanos(30);

  private static final int MAX_STAMPS = 2048;

  ArPose goal = ArPose.ORIGIN;
  boolean headingFlag;
  String name = "";
  long planId;
  boolean replanPending;
  boolean replanCounts = true;
  int replans;
  int totalReplans;
  long lastReplanNanos;
  int index;
  double bestRemaining;
  long lastProgressNanos;
  long blockedSince = -1;
  boolean aligning;
  int stopCycles;
  long startNanos;
  long stuckSince = -1;
  long backupUntil = -1;
  int backups;
  long withinSince = -1;
  double nearestGoal = Double.MAX_VALUE;

  private double[] stampX = new double[64];
  private double[] stampY = new double[64];
  private long[] stampTime = new long[64];
  private int stamps;

  void begin(ArPose g, boolean heading, String goalName, long now) {
    goal = g;
    headingFlag = heading;
    name = goalName;
    replanPending = false;
    replans = 0;
    totalReplans = 0;
    lastReplanNanos = now;
    index = 0;
    bestRemaining = Double.MAX_VALUE;
    lastProgressNanos = now;
    blockedSince = -1;
    aligning = false;
    stopCycles = 0;
    startNanos = now;
    stuckSince = -1;
    backupUntil = -1;
    backups = 0;
    withinSince = -1;
    nearestGoal = Double.MAX_VALUE;
    stamps = 0;
  }

  long nextPlanId() {
    return ++planId;
  }

  /**
   * A new path: progress is measured along it from now on; the no-progress timer restarts only if
   * {@code restartTimer} (a detour around a newly seen obstacle does not restart it, so that
   * endless detours still end in failure).
   */
  void newPath(long now, boolean restartTimer) {
    index = 0;
    bestRemaining = Double.MAX_VALUE;
    if (restartTimer) {
      lastProgressNanos = now;
    }
    blockedSince = -1;
  }

  void progressReset(long now) {
    bestRemaining = Double.MAX_VALUE;
    lastProgressNanos = now;
  }

  /** Remembers obstacle points (and forgets old ones). */
  void stamp(double[] xs, double[] ys, int n, long now) {
    int keep = 0;
    for (int i = 0; i < stamps; i++) {
      if (now - stampTime[i] <= STAMP_LIFE) {
        stampX[keep] = stampX[i];
        stampY[keep] = stampY[i];
        stampTime[keep] = stampTime[i];
        keep++;
      }
    }
    stamps = keep;
    for (int i = 0; i < n && stamps < MAX_STAMPS; i++) {
      if (stamps == stampX.length) {
        stampX = Arrays.copyOf(stampX, stamps * 2);
        stampY = Arrays.copyOf(stampY, stamps * 2);
        stampTime = Arrays.copyOf(stampTime, stamps * 2);
      }
      stampX[stamps] = xs[i];
      stampY[stamps] = ys[i];
      stampTime[stamps] = now;
      stamps++;
    }
  }

  void clearStamps() {
    stamps = 0;
  }

  double[] stampXs() {
    return Arrays.copyOf(stampX, stamps);
  }

  double[] stampYs() {
    return Arrays.copyOf(stampY, stamps);
  }

  int stampCount() {
    return stamps;
  }
}
