package org.jaria.sim;

import java.util.Locale;
import org.jaria.params.ArRobotParams;
import org.jaria.sim.robot.RobotModel;

/**
 * Robot models from ARIA robot parameter files: the footprint (RobotLengthFront/Rear, RobotWidth),
 * the sonar ring (SonarUnit), the speed limits (MaxVelocity, MaxRVelocity) and the conversion
 * factors. Any subtype JAria ships a parameter file for can be simulated: p3dx-sh, p3at-sh, p2dx,
 * amigo and more ({@link ArRobotParams#BUNDLED_SUBTYPES}).
 *
 * <p>Values a parameter file leaves to the robot's FLASH (0) get simulator defaults: maximum speed
 * 1500 mm/s and 300 °/s (at most the model's tops), accelerations 300 mm/s² and 100 °/s², laser
 * range 32 m.
 */
public final class RobotModels {

  private RobotModels() {}

  /**
   * The model of {@code subtype} (case-insensitive).
   *
   * @throws IllegalArgumentException if JAria has no parameter file for it (the message lists the
   *     subtypes it has)
   */
  public static RobotModel forSubtype(String subtype) {
    String s = subtype.trim().toLowerCase(Locale.ROOT);
    if (ArRobotParams.bundledFile(s).isEmpty()) {
      throw new IllegalArgumentException(
          "no robot model '"
              + subtype
              + "': the simulator knows "
              + ArRobotParams.BUNDLED_SUBTYPES);
    }
    return fromParams(s, ArRobotParams.forSubtype(s));
  }

  /** A model from parameters (e.g. a user's own .p file layered on the defaults). */
  public static RobotModel fromParams(String subtype, ArRobotParams p) {
    double transTop = positive(p.getAbsoluteMaxVelocity(), 2200);
    double rotTop = positive(p.getAbsoluteMaxRotVelocity(), 500);
    RobotModel.Builder b =
        RobotModel.builder(subtype)
            .robotClass(
                p.getClassName() == null || p.getClassName().isBlank()
                    ? "Pioneer"
                    : p.getClassName())
            .footprint(p.getRobotLengthFront(), p.getRobotLengthRear(), p.getRobotWidth())
            .radius(p.getRobotRadius())
            .velTops(transTop, rotTop)
            .accTops(2000, 500)
            .velMaxes(
                positive(p.getTransVelMax(), Math.min(1500, transTop)),
                positive(p.getRotVelMax(), Math.min(300, rotTop)))
            .accels(
                positive(p.getTransAccel(), 300),
                positive(p.getTransDecel(), 300),
                positive(p.getRotAccel(), 100),
                positive(p.getRotDecel(), 100))
            .conversions(
                positive(p.getDistConvFactor(), 1),
                positive(p.getAngleConvFactor(), 0.001534),
                positive(p.getVelConvFactor(), 1),
                positive(p.getRangeConvFactor(), 1),
                p.getDiffConvFactor(),
                positive(p.getVel2Divisor(), 20))
            .gyroScaler(positive(p.getGyroScaler(), 1.626))
            .bumpers(Math.min(7, p.getNumFrontBumpers()), Math.min(7, p.getNumRearBumpers()))
            .laser(
                p.getLaserX(),
                p.getLaserY(),
                p.getLaserTh(),
                positive(p.getLaserMaxRange(), 32000));
    for (int i = 0; i < Math.min(32, p.getNumSonar()); i++) {
      b.addSonar(p.getSonarX(i), p.getSonarY(i), p.getSonarTh(i));
    }
    return b.build();
  }

  private static double positive(double v, double fallback) {
    return v > 0 ? v : fallback;
  }
}
