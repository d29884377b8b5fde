package org.jaria.sim;

import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.jaria.geom.ArPose;
import org.jaria.params.ArRobotParams;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.robot.SimProfile;

/**
 * Robot models from ARIA robot parameter files: the footprint (RobotLengthFront/Rear, RobotWidth),
 * the sonar ring (SonarUnit), the speed limits (MaxVelocity, MaxRVelocity) and the conversion
 * factors. Any subtype JAria ships a parameter file for can be simulated: p3dx-sh, p3at-sh, p2dx,
 * amigo and more ({@link ArRobotParams#BUNDLED_SUBTYPES}).
 *
 * <p>Values a parameter file leaves to the robot's FLASH (0) get simulator defaults: maximum speed
 * 1500 mm/s and 300 °/s (at most the model's tops), accelerations 300 mm/s² and 100 °/s², laser
 * range 32 m.
 *
 * <p>Which models carry a laser, and where it sits, follows MobileSim's model definitions rather
 * than the parameter files (see {@link #mobileSimLaserMount}): a client that connects to the laser
 * of a default {@code p3dx-sh} finds one, as it does with MobileSim.
 */
public final class RobotModels {

  /**
   * The SICK LMS-200 of MobileSim's robot models: subtype → mount (x, y mm; th degrees) on the
   * robot. Models MobileSim defines without a laser (amigo, amigo-sh) and models it does not define
   * (p2dx) have none. {@code p3dx-sh-lms} is JAria's name for MobileSim's {@code p3dx-sh-lms200}.
   */
  private static final Map<String, ArPose> MOBILESIM_LASERS =
      Map.of(
          "p2at", new ArPose(160, 7, 0),
          "p3at", new ArPose(125, 0, 0),
          "p3at-sh", new ArPose(125, 0, 0),
          "p3dx", new ArPose(0, 0, 0),
          "p3dx-sh", new ArPose(0, 0, 0),
          "p3dx-sh-lms", new ArPose(21, 0, 0),
          "peoplebot-sh", new ArPose(21, 0, 0));

  /**
   * The top speeds of MobileSim's robot models ({@code max_speed}): subtype → {mm/s, deg/s}. A
   * robot MobileSim simulates goes no faster whatever the client asks; models it does not define
   * take its base Pioneer's 2000 mm/s and 1.74 rad/s.
   */
  private static final Map<String, double[]> MOBILESIM_TOPS =
      Map.of(
          "amigo", new double[] {500, Math.toDegrees(0.87)},
          "amigo-sh", new double[] {750, Math.toDegrees(0.87)},
          "p2at", new double[] {750, Math.toDegrees(1.74)},
          "p3at", new double[] {600, Math.toDegrees(0.75)},
          "p3at-sh", new double[] {600, Math.toDegrees(0.75)},
          "p3dx", new double[] {1000, Math.toDegrees(1.74)},
          "p3dx-sh", new double[] {1000, Math.toDegrees(1.74)},
          "p3dx-sh-lms", new double[] {1000, Math.toDegrees(1.74)},
          "peoplebot-sh", new double[] {750, Math.toDegrees(1.74)});

  /** MobileSim's base model's top speeds, for models it does not define: mm/s, deg/s. */
  private static final double[] MOBILESIM_BASE_TOPS = {2000, Math.toDegrees(1.74)};

  /**
   * How hard MobileSim stops (its E_STOP and the fake "top" accelerations its CONFIGpac reports),
   * mm/s² and deg/s².
   */
  public static final int MOBILESIM_ACC_TOP = 9999;

  private RobotModels() {}

  /**
   * The model of {@code subtype} as {@code profile} simulates it: a real Pioneer's ({@link
   * #forSubtype(String)}), or MobileSim's, whose top speeds are its model definitions' and whose
   * stops are immediate.
   *
   * @throws IllegalArgumentException if JAria has no parameter file for it
   */
  public static RobotModel forSubtype(String subtype, SimProfile profile) {
    RobotModel m = forSubtype(subtype);
    if (profile != SimProfile.MOBILESIM) {
      return m;
    }
    String s = subtype.trim().toLowerCase(Locale.ROOT);
    double[] tops = MOBILESIM_TOPS.getOrDefault(s, MOBILESIM_BASE_TOPS);
    return fromParams(s, ArRobotParams.forSubtype(s), tops, MOBILESIM_ACC_TOP);
  }

  /**
   * Where MobileSim mounts the laser of {@code subtype} (case-insensitive), or empty if MobileSim's
   * model of that robot carries none.
   */
  public static Optional<ArPose> mobileSimLaserMount(String subtype) {
    return Optional.ofNullable(MOBILESIM_LASERS.get(subtype.trim().toLowerCase(Locale.ROOT)));
  }

  /** Whether {@code subtype} carries a laser by default (as in MobileSim). */
  public static boolean carriesLaser(String subtype) {
    return mobileSimLaserMount(subtype).isPresent();
  }

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
    double[] tops = {
      positive(p.getAbsoluteMaxVelocity(), 2200), positive(p.getAbsoluteMaxRotVelocity(), 500)
    };
    return fromParams(subtype, p, tops, 0);
  }

  /**
   * A model from parameters with these top speeds ({mm/s, deg/s}) and top accelerations (0: 2000
   * mm/s², 500 deg/s²).
   */
  private static RobotModel fromParams(
      String subtype, ArRobotParams p, double[] tops, double accTop) {
    Optional<ArPose> mount = mobileSimLaserMount(subtype);
    double transTop = tops[0];
    double rotTop = tops[1];
    RobotModel.Builder b =
        RobotModel.builder(subtype)
            .robotClass(
                p.getClassName() == null || p.getClassName().isBlank()
                    ? "Pioneer"
                    : p.getClassName())
            .footprint(p.getRobotLengthFront(), p.getRobotLengthRear(), p.getRobotWidth())
            .radius(p.getRobotRadius())
            .velTops(transTop, rotTop)
            .accTops(accTop > 0 ? accTop : 2000, accTop > 0 ? accTop : 500)
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
                mount.isPresent() ? mount.get().x() : p.getLaserX(),
                mount.isPresent() ? mount.get().y() : p.getLaserY(),
                mount.isPresent() ? mount.get().th() : p.getLaserTh(),
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
