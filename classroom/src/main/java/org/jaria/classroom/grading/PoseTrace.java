package org.jaria.classroom.grading;

import java.util.Arrays;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * The simulated robot's true path, one sample per world step: where it really was (not where its
 * odometry thought), which way it faced, when, and whether it was stalled against something. An
 * assignment's checks are plain functions over it; {@link #recorded} makes one from values, to test
 * them as values.
 */
public final class PoseTrace implements AutoCloseable {

  private final SimWorld world;
  private final SimRobot robot;
  private final Runnable listener = this::sample;
  private double[] xs = new double[1024];
  private double[] ys = new double[1024];
  private double[] ts = new double[1024];
  private double[] vs = new double[1024];
  private double[] ths = new double[1024];
  private int size;
  private double firstStallSeconds = Double.NaN;
  private double firstStallX;
  private double firstStallY;
  private final long t0;

  /** Starts recording {@code robot}'s true pose after every step of {@code world}. */
  public PoseTrace(SimWorld world, SimRobot robot) {
    this.world = world;
    this.robot = robot;
    this.t0 = world.getClock().nanoTime();
    sample();
    world.addStepListener(listener);
  }

  private PoseTrace() {
    this.world = null;
    this.robot = null;
    this.t0 = 0;
  }

  /**
   * A trace of the given samples (seconds, x and y in mm, heading in degrees, speed in mm/s; all of
   * one length), never stalled: for testing checks as plain functions.
   */
  public static PoseTrace recorded(
      double[] seconds, double[] x, double[] y, double[] thDeg, double[] speed) {
    int n = seconds.length;
    if (x.length != n || y.length != n || thDeg.length != n || speed.length != n) {
      throw new IllegalArgumentException("every sample needs a time, x, y, heading and speed");
    }
    PoseTrace t = new PoseTrace();
    t.ts = Arrays.copyOf(seconds, Math.max(1, n));
    t.xs = Arrays.copyOf(x, Math.max(1, n));
    t.ys = Arrays.copyOf(y, Math.max(1, n));
    t.ths = Arrays.copyOf(thDeg, Math.max(1, n));
    t.vs = Arrays.copyOf(speed, Math.max(1, n));
    t.size = n;
    return t;
  }

  private void sample() {
    if (size == xs.length) {
      xs = Arrays.copyOf(xs, size * 2);
      ys = Arrays.copyOf(ys, size * 2);
      ts = Arrays.copyOf(ts, size * 2);
      vs = Arrays.copyOf(vs, size * 2);
      ths = Arrays.copyOf(ths, size * 2);
    }
    ArPose p = robot.getTruePose();
    xs[size] = p.x();
    ys[size] = p.y();
    ts[size] = (world.getClock().nanoTime() - t0) / 1e9;
    vs[size] = Math.abs(robot.getVel());
    ths[size] = p.th();
    if (Double.isNaN(firstStallSeconds) && robot.isStalled()) {
      firstStallSeconds = ts[size];
      firstStallX = p.x();
      firstStallY = p.y();
    }
    size++;
  }

  /** Number of samples. */
  public int size() {
    return size;
  }

  /** X of sample i, mm. */
  public double x(int i) {
    return xs[i];
  }

  /** Y of sample i, mm. */
  public double y(int i) {
    return ys[i];
  }

  /** The heading of sample i, degrees (-180 to 180). */
  public double th(int i) {
    return ths[i];
  }

  /** Seconds since recording began, of sample i. */
  public double t(int i) {
    return ts[i];
  }

  /** The robot's true speed at sample i, mm/s (absolute). */
  public double speed(int i) {
    return vs[i];
  }

  /**
   * Index of the first sample from {@code from} on within {@code radius} of (x, y) where the robot
   * was (nearly) standing still, or -1.
   */
  public int firstStopWithin(double x, double y, double radius, double maxSpeed, int from) {
    for (int i = Math.max(0, from); i < size; i++) {
      if (vs[i] <= maxSpeed && Math.hypot(xs[i] - x, ys[i] - y) <= radius) {
        return i;
      }
    }
    return -1;
  }

  /** Whether the robot was ever stalled (pushing against something). */
  public boolean everStalled() {
    return !Double.isNaN(firstStallSeconds);
  }

  /** When it first stalled, seconds, or NaN. */
  public double firstStallSeconds() {
    return firstStallSeconds;
  }

  /** Where it first stalled, as text. */
  public String firstStallWhere() {
    return Fmt.xy(firstStallX, firstStallY);
  }

  /** Index of the sample closest to (x, y) from sample {@code from} on. */
  public int closestTo(double x, double y, int from) {
    int best = -1;
    double bestD = Double.POSITIVE_INFINITY;
    for (int i = Math.max(0, from); i < size; i++) {
      double d = Math.hypot(xs[i] - x, ys[i] - y);
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  }

  /** Index of the first sample within {@code radius} of (x, y) from sample {@code from}, or -1. */
  public int firstWithin(double x, double y, double radius, int from) {
    for (int i = Math.max(0, from); i < size; i++) {
      if (Math.hypot(xs[i] - x, ys[i] - y) <= radius) {
        return i;
      }
    }
    return -1;
  }

  /** Distance from sample i to (x, y), mm. */
  public double distance(int i, double x, double y) {
    return Math.hypot(xs[i] - x, ys[i] - y);
  }

  @Override
  public void close() {
    if (world != null) {
      world.removeStepListener(listener);
    }
  }
}
