package org.jaria.sim.robot;

import java.util.random.RandomGenerator;
import org.jaria.geom.ArMath;
import org.jaria.sim.OdometryError;

/**
 * The wheel encoders and the position integration of the robot's controller: what the robot
 * believes about its own motion. The true motion of each tick goes in; the configured {@link
 * OdometryError}, the DRIFTFACTOR, TICKSMM and REVCOUNT settings bend it on the way to the encoder
 * counts and the odometry pose.
 *
 * <p>With the default settings and no error, odometry equals the true motion exactly. Changing
 * TICKSMM or REVCOUNT away from the simulated hardware's values scales distances or turns, as it
 * would on a real robot.
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class Odometry {

  /** Encoder ticks per mm of wheel travel of the simulated hardware. */
  public static final double TICKS_PER_MM = 32;

  private final OdometryError error;
  private final RandomGenerator rng;
  private final double track;
  private final double trueRevCount;

  private double ticksMmSetting;
  private double revCountSetting;
  private int driftFactor;

  private double x;
  private double y;

  /**
   * The heading without wrapping, degrees. The wrapped heading ({@link #getTh}) is derived from it,
   * and so is the heading counter (THPOS), which counts angle units round and round (see {@link
   * #getThUnits}).
   */
  private double turned;

  private double encLeft;
  private double encRight;
  private double lastMeasured;

  /** MobileSim's scale errors in use (RANDOM_EACH_UPDATE, RANDOM_INIT), fractions. */
  private double scaleTrans;

  private double scaleRot;

  /** Simulated time since RANDOM_EACH_UPDATE last drew its factors, ms. */
  private double sinceDraw;

  /**
   * Odometry for wheels {@code trackWidth} mm apart.
   *
   * @param rng source of the random error (only drawn from while the robot moves)
   */
  public Odometry(double trackWidth, OdometryError error, RandomGenerator rng) {
    this.track = trackWidth;
    this.error = error;
    this.rng = rng;
    this.trueRevCount = Math.PI * trackWidth * TICKS_PER_MM;
    resetSettings();
    if (error.mode() == OdometryError.Mode.RANDOM_INIT
        || error.mode() == OdometryError.Mode.RANDOM_EACH_UPDATE) {
      drawScales();
    }
  }

  /** New MobileSim scale errors, uniform within the error's bounds. */
  private void drawScales() {
    scaleTrans = uniform(error.transPerMetre());
    scaleRot = uniform(error.rotPerRadian());
    sinceDraw = 0;
  }

  private double uniform(double bound) {
    return bound == 0 ? 0 : (rng.nextDouble() * 2 - 1) * bound;
  }

  /** Returns TICKSMM, REVCOUNT and DRIFTFACTOR to the hardware values. */
  public void resetSettings() {
    ticksMmSetting = TICKS_PER_MM;
    revCountSetting = trueRevCount;
    driftFactor = 0;
  }

  /** SETO: sets the odometry pose (mm, mm, degrees). */
  public void setPose(double px, double py, double thDeg) {
    x = px;
    y = py;
    turned = ArMath.fixAngle(thDeg);
  }

  /**
   * Measures the true motion of one tick of {@code dtMs} ms ({@code ds} mm forward along the arc,
   * {@code dthDeg} turned) and integrates it.
   */
  public void update(double ds, double dthDeg, double dtMs) {
    if (error.mode() == OdometryError.Mode.RANDOM_EACH_UPDATE) {
      // MobileSim draws at every update of its world, moving or not
      sinceDraw += dtMs;
      if (sinceDraw >= OdometryError.UPDATE_MILLIS) {
        drawScales();
      }
    }
    if (ds == 0 && dthDeg == 0) {
      lastMeasured = 0;
      return;
    }
    double dth = Math.toRadians(dthDeg);
    switch (error.mode()) {
      case NONE -> {}
      case CONSTANT -> {
        ds *= 1 + error.transPerMetre();
        dth *= 1 + error.rotPerRadian();
      }
      case RANDOM_EACH_UPDATE, RANDOM_INIT -> {
        ds *= 1 + scaleTrans;
        dth *= 1 + scaleRot;
      }
      case RANDOM -> {
        ds += rng.nextGaussian() * error.transPerMetre() * Math.sqrt(Math.abs(ds) * 1000);
        dth += rng.nextGaussian() * error.rotPerRadian() * Math.sqrt(Math.abs(dth));
      }
    }
    double left = (ds - dth * track / 2) * (1 + driftFactor / 8192.0);
    double right = ds + dth * track / 2;
    encLeft += left * TICKS_PER_MM;
    encRight += right * TICKS_PER_MM;
    double dsOdo = (left + right) / 2 * TICKS_PER_MM / ticksMmSetting;
    double dthOdo = (right - left) * TICKS_PER_MM * Math.PI / revCountSetting;
    double mid = Math.toRadians(getTh()) + dthOdo / 2;
    x += dsOdo * Math.cos(mid);
    y += dsOdo * Math.sin(mid);
    turned += Math.toDegrees(dthOdo);
    lastMeasured = dsOdo;
  }

  /** Distance the odometry measured in the last update, mm (feeds MOVE). */
  public double lastMeasured() {
    return lastMeasured;
  }

  /** Odometry x, mm. */
  public double getX() {
    return x;
  }

  /** Odometry y, mm. */
  public double getY() {
    return y;
  }

  /** Odometry heading, degrees (−180, 180]. */
  public double getTh() {
    return ArMath.fixAngle(turned);
  }

  /**
   * The heading as the SIP's THPOS carries it: a counter of {@code radPerUnit} angle units that
   * wraps at 4096 (as ARCOS's does, and as ARIA unwraps it), in −2048..2047.
   *
   * <p>Why not {@code round(getTh() / radPerUnit)}: with a parameter file's {@code AngleConvFactor}
   * of 0.00153 a turn is 4107 units, not 4096, so a heading that jumps from +180° to −180° jumps by
   * 4107 units and a robot unwrapping modulo 4096 lost 11 units (0.94°) at every crossing of ±180°.
   * Counting units from the unwrapped heading keeps every difference of two SIPs exact.
   */
  public int getThUnits(double radPerUnit) {
    long units = Math.round(Math.toRadians(turned) / radPerUnit);
    return (int) (Math.floorMod(units + 2048, 4096L) - 2048);
  }

  /** Left encoder count. */
  public int getLeftEncoder() {
    return (int) (long) Math.floor(encLeft);
  }

  /** Right encoder count. */
  public int getRightEncoder() {
    return (int) (long) Math.floor(encRight);
  }

  /** TICKSMM: encoder ticks per mm the controller assumes. */
  public void setTicksMm(int ticks) {
    if (ticks > 0) {
      ticksMmSetting = ticks;
    }
  }

  /** REVCOUNT: encoder tick difference the controller assumes for a 180° turn. */
  public void setRevCount(int ticks) {
    if (ticks > 0) {
      revCountSetting = ticks;
    }
  }

  /** DRIFTFACTOR: left-wheel correction in 1/8192 units. */
  public void setDriftFactor(int f) {
    driftFactor = f;
  }

  /** TICKSMM as reported in CONFIGpac. */
  public int getTicksMm() {
    return (int) Math.round(ticksMmSetting);
  }

  /** REVCOUNT as reported in CONFIGpac. */
  public int getRevCount() {
    return (int) Math.min(65535, Math.round(revCountSetting));
  }

  /** DRIFTFACTOR as reported in CONFIGpac. */
  public int getDriftFactor() {
    return driftFactor;
  }

  /** The configured error model. */
  public OdometryError getError() {
    return error;
  }
}
