package org.jaria.arnl;

import org.jaria.arnl.plan.LocalPlanner;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigArg;
import org.jaria.config.ArPriority;

/**
 * The parameters of {@link ArPathPlanningTask}, registered in the "Path planning" section of an
 * {@link ArConfig} (as in ARNL's {@code arnl.p}). Grid parameters take effect at the next goal;
 * driving parameters at once.
 */
public final class PathPlanningParams {

  /** The config section these parameters live in. */
  public static final String SECTION = "Path planning";

  final ArConfigArg planRes =
      ArConfigArg.ofDouble("PlanRes", 100, "cell size of the planning grid, mm", 10, 1000);
  final ArConfigArg planFreeSpace =
      ArConfigArg.ofDouble(
          "PlanFreeSpace",
          1000,
          "clearance beyond which a cell costs no extra (paths keep this far from walls if they"
              + " can), mm",
          100,
          10000);
  final ArConfigArg clearanceCost =
      ArConfigArg.ofDouble(
          "ClearanceCost", 4, "extra cost of a cell at the robot's edge (1 = double)", 0, 1000);
  final ArConfigArg width =
      ArConfigArg.ofDouble("Width", 0, "robot width, mm (0 = from the robot parameters)", 0, 5000);
  final ArConfigArg planPadding =
      ArConfigArg.ofDouble(
          "PlanPadding",
          40,
          "the planned path keeps the robot's side at least this far from obstacles, mm",
          0,
          2000);
  final ArConfigArg sideClearance =
      ArConfigArg.ofDouble(
          "SideClearance",
          30,
          "while driving, obstacles closer than this to the robot's side stop a trajectory, mm",
          0,
          2000);
  final ArConfigArg collisionRange =
      ArConfigArg.ofDouble(
          "CollisionRange",
          1500,
          "sonar obstacles farther than this are ignored (sonar places far ones poorly), mm",
          200,
          10000);
  final ArConfigArg maxSpeed =
      ArConfigArg.ofDouble("MaxSpeed", 600, "top speed while following a path, mm/s", 10, 3000);
  final ArConfigArg maxRotSpeed =
      ArConfigArg.ofDouble("MaxRotSpeed", 60, "top rotational speed, deg/s", 1, 360);
  final ArConfigArg transAccel =
      ArConfigArg.ofDouble("TransAccel", 300, "acceleration assumed, mm/s²", 10, 5000);
  final ArConfigArg transDecel =
      ArConfigArg.ofDouble("TransDecel", 300, "deceleration assumed for braking, mm/s²", 10, 5000);
  final ArConfigArg rotAccel =
      ArConfigArg.ofDouble("RotAccel", 100, "rotational acceleration assumed, deg/s²", 1, 2000);
  final ArConfigArg goalDistanceTolerance =
      ArConfigArg.ofDouble(
          "GoalDistanceTolerance", 200, "the goal is reached this close, mm", 10, 5000);
  final ArConfigArg goalAngleTolerance =
      ArConfigArg.ofDouble(
          "GoalAngleTolerance", 10, "heading tolerance at a goal with heading, degrees", 1, 180);
  final ArConfigArg secsToFail =
      ArConfigArg.ofDouble(
          "SecsToFail",
          10,
          "seconds without progress before replanning (and, after MaxReplans, failing)",
          1,
          600);
  final ArConfigArg maxReplans =
      ArConfigArg.ofInt("MaxReplans", 4, "replans allowed per goal before failing", 0, 100);
  final ArConfigArg headingWt =
      ArConfigArg.ofDouble("HeadingWt", 1, "local planner: weight of heading to the path", 0, 100);
  final ArConfigArg distanceWt =
      ArConfigArg.ofDouble(
          "DistanceWt", 0.6, "local planner: weight of staying near the path", 0, 100);
  final ArConfigArg clearanceWt =
      ArConfigArg.ofDouble("ClearanceWt", 0.3, "local planner: weight of clearance", 0, 100);
  final ArConfigArg velocityWt =
      ArConfigArg.ofDouble("VelocityWt", 0.4, "local planner: weight of speed", 0, 100);
  final ArConfigArg linVelIncrements =
      ArConfigArg.ofInt("LinVelIncrements", 7, "local planner: speeds tried", 1, 101);
  final ArConfigArg rotVelIncrements =
      ArConfigArg.ofInt("RotVelIncrements", 15, "local planner: turn rates tried", 1, 101);
  final ArConfigArg lookAhead =
      ArConfigArg.ofDouble(
          "LookAhead", 800, "local planner steers at the path point this far ahead, mm", 100, 5000);
  final ArConfigArg alignAngle =
      ArConfigArg.ofDouble(
          "AlignAngle", 50, "turn in place when the path is more than this off, degrees", 5, 180);
  final ArConfigArg localHorizon =
      ArConfigArg.ofDouble(
          "LocalHorizon", 1.8, "local planner looks this far ahead in time, s", 0.3, 10);
  final ArConfigArg mapMatchDistance =
      ArConfigArg.ofDouble(
          "MapMatchDistance",
          200,
          "a sonar echo this close to a mapped wall is the wall, not a new obstacle, mm",
          0,
          2000);
  final ArConfigArg useSonar =
      ArConfigArg.ofBool("UseSonar", true, "avoid unmapped obstacles seen by the sonar");

  private final ArConfig config;

  /** The parameters with their default values, in a config of their own. */
  public PathPlanningParams() {
    this(new ArConfig());
  }

  /** The parameters with their default values, registered in {@code config}. */
  public PathPlanningParams(ArConfig config) {
    this.config = config;
    config.addSection(SECTION, "Path planning and following (ArPathPlanningTask)");
    ArConfigArg[] important = {maxSpeed, maxRotSpeed, goalDistanceTolerance, planRes, secsToFail};
    ArConfigArg[] normal = {
      planFreeSpace,
      clearanceCost,
      width,
      planPadding,
      sideClearance,
      collisionRange,
      transAccel,
      transDecel,
      rotAccel,
      goalAngleTolerance,
      maxReplans,
      useSonar,
      mapMatchDistance
    };
    ArConfigArg[] expert = {
      headingWt,
      distanceWt,
      clearanceWt,
      velocityWt,
      linVelIncrements,
      rotVelIncrements,
      lookAhead,
      alignAngle,
      localHorizon
    };
    for (ArConfigArg a : important) {
      config.addParam(a, SECTION, ArPriority.IMPORTANT);
    }
    for (ArConfigArg a : normal) {
      config.addParam(a, SECTION, ArPriority.NORMAL);
    }
    for (ArConfigArg a : expert) {
      config.addParam(a, SECTION, ArPriority.EXPERT);
    }
  }

  /** The config the parameters are registered in. */
  public ArConfig getConfig() {
    return config;
  }

  /**
   * The local planner settings these values describe, for a robot of half-width {@code half}
   * reaching {@code front} ahead of and {@code rear} behind its centre.
   */
  LocalPlanner.Params localParams(double half, double front, double rear) {
    return new LocalPlanner.Params(
        maxSpeed.getDouble(),
        maxRotSpeed.getDouble(),
        transAccel.getDouble(),
        transDecel.getDouble(),
        rotAccel.getDouble(),
        half + sideClearance.getDouble(),
        front,
        rear,
        half,
        sideClearance.getDouble(),
        localHorizon.getDouble(),
        0.5,
        linVelIncrements.getInt(),
        rotVelIncrements.getInt(),
        headingWt.getDouble(),
        distanceWt.getDouble(),
        clearanceWt.getDouble(),
        velocityWt.getDouble(),
        lookAhead.getDouble(),
        alignAngle.getDouble());
  }

  /** Top speed, mm/s. */
  public double getMaxSpeed() {
    return maxSpeed.getDouble();
  }

  /** Sets the top speed, mm/s. */
  public void setMaxSpeed(double v) {
    maxSpeed.setDouble(v);
  }

  /** Planning grid cell size, mm. */
  public double getPlanMapResolution() {
    return planRes.getDouble();
  }

  /** Sets the planning grid cell size, mm. */
  public void setPlanMapResolution(double mm) {
    planRes.setDouble(mm);
  }

  /** Goal distance tolerance, mm. */
  public double getGoalDistanceTolerance() {
    return goalDistanceTolerance.getDouble();
  }

  /** Sets the goal distance tolerance, mm. */
  public void setGoalDistanceTolerance(double mm) {
    goalDistanceTolerance.setDouble(mm);
  }

  /** Seconds without progress before replanning. */
  public double getSecsToFail() {
    return secsToFail.getDouble();
  }

  /** Sets the seconds without progress before replanning. */
  public void setSecsToFail(double s) {
    secsToFail.setDouble(s);
  }

  /** The parameter called {@code name} (case-insensitive). */
  public ArConfigArg get(String name) {
    return config
        .findParam(SECTION, name)
        .orElseThrow(() -> new IllegalArgumentException("no path planning parameter " + name));
  }
}
