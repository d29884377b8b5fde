package org.jaria.laser.log;

import java.util.Arrays;
import java.util.Objects;
import java.util.Optional;
import org.jaria.geom.ArPose;

/**
 * One laser sweep of a scan log with the robot's pose when it was taken. Readings are points in the
 * laser's own frame (x ahead of the laser, y to its left, mm) in sweep order; a reading with no
 * echo is {@code (0, 0)} as ARIA writes it, and a value the log spelled as {@code nan} or {@code
 * inf}, or beyond a kilometre, is kept as NaN so it counts as no echo too ({@link #hasEcho}).
 * Immutable.
 */
public final class LoggedScan implements ScanLogEntry {

  private final int id;
  private final double time;
  private final double vel;
  private final double rotVel;
  private final double latVel;
  private final ArPose robotPose;
  private final ArPose globalPose;
  private final double[] xs;
  private final double[] ys;

  /**
   * A scan.
   *
   * @param id the scan's number in the log (ARIA counts from 0)
   * @param time seconds since logging started
   * @param vel the robot's velocity, mm/s
   * @param rotVel its rotational velocity, deg/s
   * @param latVel its lateral velocity, mm/s
   * @param robotPose the odometry pose when the readings were taken ({@code robot:})
   * @param globalPose the localized pose then ({@code robotGlobal:}), or null if not logged
   * @param xs readings' x in the laser's frame, mm
   * @param ys readings' y in the laser's frame, mm
   * @throws IllegalArgumentException if the arrays differ in length
   */
  public LoggedScan(
      int id,
      double time,
      double vel,
      double rotVel,
      double latVel,
      ArPose robotPose,
      ArPose globalPose,
      double[] xs,
      double[] ys) {
    this(id, time, vel, rotVel, latVel, robotPose, globalPose, xs.clone(), ys.clone(), true);
  }

  /** Takes the arrays without copying them (the reader's fresh arrays). */
  LoggedScan(
      int id,
      double time,
      double vel,
      double rotVel,
      double latVel,
      ArPose robotPose,
      ArPose globalPose,
      double[] xs,
      double[] ys,
      boolean owned) {
    if (xs.length != ys.length) {
      throw new IllegalArgumentException(
          "a scan needs one y per x: " + xs.length + " x, " + ys.length + " y");
    }
    this.id = id;
    this.time = time;
    this.vel = vel;
    this.rotVel = rotVel;
    this.latVel = latVel;
    this.robotPose = Objects.requireNonNull(robotPose, "robotPose");
    this.globalPose = globalPose;
    this.xs = xs;
    this.ys = ys;
  }

  /** The scan's number in the log. */
  public int id() {
    return id;
  }

  @Override
  public double time() {
    return time;
  }

  /** The robot's velocity when the scan was logged, mm/s. */
  public double vel() {
    return vel;
  }

  /** The robot's rotational velocity, deg/s. */
  public double rotVel() {
    return rotVel;
  }

  /** The robot's lateral velocity, mm/s. */
  public double latVel() {
    return latVel;
  }

  /** The robot's odometry pose when the readings were taken (the log's {@code robot:} line). */
  public ArPose robotPose() {
    return robotPose;
  }

  /** The robot's localized pose then ({@code robotGlobal:}), if the log has it. */
  public Optional<ArPose> globalPose() {
    return Optional.ofNullable(globalPose);
  }

  /** Number of readings, with and without echo. */
  public int size() {
    return xs.length;
  }

  /** X of reading {@code i} in the laser's frame, mm (NaN for a damaged value). */
  public double x(int i) {
    return xs[i];
  }

  /** Y of reading {@code i} in the laser's frame, mm. */
  public double y(int i) {
    return ys[i];
  }

  /** Distance of reading {@code i} from the laser, mm (0 for no echo, NaN if damaged). */
  public double range(int i) {
    double x = xs[i];
    double y = ys[i];
    return Math.sqrt(x * x + y * y);
  }

  /** Whether reading {@code i} saw something: finite and not ARIA's {@code 0 0}. */
  public boolean hasEcho(int i) {
    double x = xs[i];
    double y = ys[i];
    return Double.isFinite(x) && Double.isFinite(y) && (x != 0 || y != 0);
  }

  /** Number of readings that saw something. */
  public int echoCount() {
    int n = 0;
    for (int i = 0; i < xs.length; i++) {
      if (hasEcho(i)) {
        n++;
      }
    }
    return n;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof LoggedScan s
        && id == s.id
        && Double.compare(time, s.time) == 0
        && Double.compare(vel, s.vel) == 0
        && Double.compare(rotVel, s.rotVel) == 0
        && Double.compare(latVel, s.latVel) == 0
        && robotPose.equals(s.robotPose)
        && Objects.equals(globalPose, s.globalPose)
        && Arrays.equals(xs, s.xs)
        && Arrays.equals(ys, s.ys);
  }

  @Override
  public int hashCode() {
    return Objects.hash(id, time, robotPose, Arrays.hashCode(xs), Arrays.hashCode(ys));
  }

  @Override
  public String toString() {
    return "LoggedScan#" + id + " t=" + time + " at " + robotPose + ", " + xs.length + " readings";
  }
}
