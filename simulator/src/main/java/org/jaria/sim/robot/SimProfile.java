package org.jaria.sim.robot;

import java.util.Locale;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SonarOptions;

/**
 * Which robot the simulator pretends to be: MobileSim's simulated Pioneer, or a real Pioneer with
 * ARCOS. A program can tell them apart, so a simulator plays one of them at a time.
 *
 * <p>{@link #MOBILESIM} behaves as MobileSim (and its successor AMRISim) does, so that a program
 * that was written and tested against MobileSim sees the same robot: one sonar ray per transducer
 * and all the transducers' readings in every SIP, motors enabled when the robot is made,
 * MobileSim's configuration values (CONFIGpac) and status bytes, odometry that drifts a little by
 * default, no gripper.
 *
 * <p>{@link #PIONEER} behaves as a real Pioneer 3 with ARCOS: a sonar cone, a sonar cycle that
 * fires one transducer per array at a time (a few readings per SIP), motors disabled until the
 * program enables them, the configuration of the model's parameter file, exact odometry unless an
 * error is asked for, a gripper.
 */
public enum SimProfile {
  /** MobileSim's simulated robot. */
  MOBILESIM,
  /** A real Pioneer with ARCOS. */
  PIONEER;

  /**
   * MobileSim's default odometry error: each 100 ms the distance and the turn are scaled by a
   * factor drawn uniformly from 1 ± 0.0075 (its models' {@code odom_error} and its default {@code
   * random_each_update} mode).
   */
  public static final OdometryError MOBILESIM_ODOMETRY =
      OdometryError.randomEachUpdate(OdometryError.MOBILESIM_ERROR, OdometryError.MOBILESIM_ERROR);

  /** How sonar sees the world in this profile. */
  public SonarOptions sonar() {
    return this == MOBILESIM ? SonarOptions.MOBILESIM : SonarOptions.DEFAULTS;
  }

  /** How odometry errs unless a program or the command line asks for something else. */
  public OdometryError odometryError() {
    return this == MOBILESIM ? MOBILESIM_ODOMETRY : OdometryError.NONE;
  }

  /**
   * Whether the motors are on when the robot is made. MobileSim's are (a session's end turns them
   * off); a real Pioneer's wait for the program's ENABLE at every connection.
   */
  public boolean motorsEnabledAtStart() {
    return this == MOBILESIM;
  }

  /** Whether a robot carries a gripper unless told otherwise (MobileSim simulates none). */
  public boolean gripperByDefault() {
    return this == PIONEER;
  }

  /** The name on the command line: {@code mobilesim} or {@code pioneer}. */
  public String cliName() {
    return name().toLowerCase(Locale.ROOT);
  }

  /**
   * The profile called {@code name} ({@code mobilesim} or {@code pioneer}, any case).
   *
   * @throws IllegalArgumentException naming the two profiles
   */
  public static SimProfile parse(String name) {
    String n = name == null ? "" : name.trim().toLowerCase(Locale.ROOT);
    for (SimProfile p : values()) {
      if (p.cliName().equals(n)) {
        return p;
      }
    }
    throw new IllegalArgumentException(
        "no simulator profile '"
            + name
            + "': use mobilesim (behave as MobileSim) or pioneer (behave as a real Pioneer)");
  }
}
