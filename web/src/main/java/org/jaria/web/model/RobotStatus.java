package org.jaria.web.model;

import java.util.Objects;

/**
 * What the status bar says about a robot.
 *
 * @param vel translational velocity, mm/s
 * @param rotVel rotational velocity, deg/s
 * @param batteryVolts battery voltage, or NaN when unknown (the simulator's world alone)
 * @param motorsEnabled whether the motors are on
 * @param stalled whether a wheel is stalled or a bumper pressed
 * @param mode what drives it ("no client", "client connected", "goal: ...", "teleop", ...)
 * @param localizationScore the localization's score 0..1, or NaN when nothing localizes it
 */
public record RobotStatus(
    double vel,
    double rotVel,
    double batteryVolts,
    boolean motorsEnabled,
    boolean stalled,
    String mode,
    double localizationScore) {

  /** Checks. */
  public RobotStatus {
    Objects.requireNonNull(mode, "mode");
  }
}
