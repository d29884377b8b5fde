package org.jaria.sim.robot;

import java.util.random.RandomGenerator;
import org.jaria.geom.ArMath;
import org.jaria.sim.world.RayHit;
import org.jaria.sim.world.WorldGeometry;

/**
 * A simulated laser range finder (a SICK LMS-200 as MobileSim models it): one ray per reading over
 * the field of view (default −90° to +90° at 1°, 181 readings), nearest hit with small seeded
 * noise, or {@link #NO_ECHO_MM} for a beam that hits nothing within the maximum range. Scans are
 * taken on request (once per SIP cycle while streaming).
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class LaserModel {

  /** Standard deviation of the range noise, mm. */
  public static final double NOISE_MM = 5;

  /**
   * The range sent for a beam with no echo, mm: MobileSim's (its LMS-200's 32.767 m "maximum
   * range"), above the 32 m every ARIA laser class takes as its largest valid reading, so ARIA (and
   * JAria) drop it as "no reading" instead of seeing a wall 32 m away.
   */
  public static final int NO_ECHO_MM = 32767;

  private final RobotModel model;
  private final RandomGenerator rng;
  private final RayHit hit = new RayHit();
  private double startDeg = -90;
  private double endDeg = 90;
  private double incDeg = 1;
  private int[] ranges = new int[0];
  private boolean[] echo = new boolean[0];
  private double originX;
  private double originY;
  private double originTh;
  private boolean legacyCommands;
  private final SrisimLaserSetup srisim = new SrisimLaserSetup();

  /**
   * Whether the beams are spread as MobileSim's laser spreads them: {@code n} readings over the
   * field of view {@code span} lie {@code span / n} apart (not {@code span / (n − 1)}), so the last
   * one falls one increment short of the end: a 181-reading scan of 180° has its beams 0.9945°
   * apart and its last at 89.0°, while ARIA places reading k at −90 + k°.
   */
  private final boolean mobileSimSpacing;

  /** A laser mounted as {@code model} says. */
  public LaserModel(RobotModel model, RandomGenerator rng) {
    this(model, rng, false);
  }

  /**
   * A laser mounted as {@code model} says, its beams spread as MobileSim's are ({@code
   * mobileSimSpacing}) or exactly one increment apart.
   */
  public LaserModel(RobotModel model, RandomGenerator rng, boolean mobileSimSpacing) {
    this.model = model;
    this.rng = rng;
    this.mobileSimSpacing = mobileSimSpacing;
  }

  /**
   * Whether the robot reads commands 35–38 as this laser's old set-up commands (enable, start, end,
   * increment) instead of their ARCOS meanings.
   */
  public boolean acceptsLegacyCommands() {
    return legacyCommands;
  }

  /** Makes the robot read commands 35–38 as this laser's old set-up commands (or not). */
  public void setAcceptsLegacyCommands(boolean on) {
    legacyCommands = on;
  }

  /** Returns to the default field of view and resolution (a new session). */
  public void resetSettings() {
    startDeg = -90;
    endDeg = 90;
    incDeg = 1;
    srisim.reset();
  }

  /** The session's SRISim set-up sequence (see {@link SrisimLaserSetup}). */
  public SrisimLaserSetup srisimSetup() {
    return srisim;
  }

  /** Sets the start of the field of view, degrees. */
  public void setStart(double deg) {
    startDeg = ArMath.clamp(deg, -180, 180);
  }

  /** Sets the end of the field of view, degrees. */
  public void setEnd(double deg) {
    endDeg = ArMath.clamp(deg, -180, 180);
  }

  /** Sets the angle between readings, degrees (at least 0.1). */
  public void setIncrement(double deg) {
    incDeg = Math.max(0.1, Math.abs(deg));
  }

  /** Number of readings per scan. */
  public int readingCount() {
    return (int) Math.floor(Math.abs(endDeg - startDeg) / incDeg + 1e-9) + 1;
  }

  /** First reading's angle relative to the laser, degrees. */
  public double getStart() {
    return Math.min(startDeg, endDeg);
  }

  /** Angle between readings, degrees (as set: what the client asked for). */
  public double getIncrement() {
    return incDeg;
  }

  /**
   * Angle between the beams of a scan, degrees (see {@link #LaserModel(RobotModel, RandomGenerator,
   * boolean)}).
   */
  public double beamSpacing() {
    return mobileSimSpacing ? Math.abs(endDeg - startDeg) / readingCount() : incDeg;
  }

  /** Scans from the robot's true pose (x, y mm, thRad). */
  public void scan(double x, double y, double thRad, WorldGeometry world, int self) {
    int count = readingCount();
    if (ranges.length != count) {
      ranges = new int[count];
      echo = new boolean[count];
    }
    double c = Math.cos(thRad);
    double s = Math.sin(thRad);
    originX = x + c * model.getLaserX() - s * model.getLaserY();
    originY = y + s * model.getLaserX() + c * model.getLaserY();
    originTh = Math.toDegrees(thRad) + model.getLaserTh();
    double max = model.getLaserMaxRange();
    double first = Math.toRadians(originTh + getStart());
    double inc = Math.toRadians(beamSpacing());
    for (int k = 0; k < count; k++) {
      double a = first + k * inc;
      world.cast(originX, originY, Math.cos(a), Math.sin(a), max, self, hit);
      if (hit.hit()) {
        double r = hit.distance + rng.nextGaussian() * NOISE_MM;
        ranges[k] = (int) Math.round(ArMath.clamp(r, 0, max));
        echo[k] = true;
      } else {
        ranges[k] = NO_ECHO_MM;
        echo[k] = false;
      }
    }
  }

  /** Ranges of the last scan as sent, mm ({@link #NO_ECHO_MM} where nothing was hit; a copy). */
  public int[] ranges() {
    return ranges.clone();
  }

  /** Range {@code k} of the last scan as sent, mm ({@link #NO_ECHO_MM} for no echo). */
  public int range(int k) {
    return ranges[k];
  }

  /** Whether reading {@code k} of the last scan hit something. */
  public boolean echo(int k) {
    return echo[k];
  }

  /** Readings in the last scan. */
  public int lastCount() {
    return ranges.length;
  }

  /** World x of the laser at the last scan. */
  public double originX() {
    return originX;
  }

  /** World y of the laser at the last scan. */
  public double originY() {
    return originY;
  }

  /** World heading of the laser at the last scan, degrees. */
  public double originTh() {
    return originTh;
  }
}
