package org.jaria.ptz;

import org.jaria.robot.ArRobot;

/**
 * A Directed Perception pan-tilt unit (ARIA's {@code ArDPPTU}), the PTU-46-17.5 by default: one
 * position step is 0.0514° on both axes (0.0129° of tilt on the PTU-46-70), pan ±159°, tilt
 * −47°..+31° (used as ±31° here). Commands are ASCII: PP/TP absolute position, PS/TS speed, I
 * immediate mode, R reset, H halt.
 */
public class ArDPPTU extends ArPTZ {

  /** The models JAria knows, with their step sizes. */
  public enum Model {
    /** PTU-46-17.5: 0.0514° per step on both axes. */
    PANTILT_PTU46(0.0514, 0.0514),
    /** PTU-46-70: 0.0514° per pan step, 0.0129° per tilt step. */
    PANTILT_PTU46_70(0.0514, 0.0129);

    final double panDegPerStep;
    final double tiltDegPerStep;

    Model(double pan, double tilt) {
      this.panDegPerStep = pan;
      this.tiltDegPerStep = tilt;
    }
  }

  /** Largest pan, degrees. */
  public static final double MAX_PAN = 158;

  /** Largest tilt, degrees. */
  public static final double MAX_TILT = 30;

  private final Model model;

  /** A PTU-46-17.5 on {@code robot}'s AUX1 port. */
  public ArDPPTU(ArRobot robot) {
    this(robot, Model.PANTILT_PTU46);
  }

  /** A unit of {@code model} on {@code robot}'s AUX1 port. */
  public ArDPPTU(ArRobot robot, Model model) {
    super(robot);
    this.model = model;
  }

  @Override
  public boolean init() {
    return send(DpptuText.command("I")) && panTilt(0, 0);
  }

  @Override
  public double getMaxPan() {
    return MAX_PAN;
  }

  @Override
  public double getMaxTilt() {
    return MAX_TILT;
  }

  @Override
  protected boolean panTiltClamped(double panDeg, double tiltDeg) {
    return send(DpptuText.command("PP", (int) Math.round(panDeg / model.panDegPerStep)))
        && send(DpptuText.command("TP", (int) Math.round(tiltDeg / model.tiltDegPerStep)));
  }

  /** Sets the pan speed, degrees per second. */
  public boolean panSlew(double degPerSec) {
    return send(DpptuText.command("PS", (int) Math.round(degPerSec / model.panDegPerStep)));
  }

  /** Sets the tilt speed, degrees per second. */
  public boolean tiltSlew(double degPerSec) {
    return send(DpptuText.command("TS", (int) Math.round(degPerSec / model.tiltDegPerStep)));
  }

  /** Recalibrates both axes (the unit sweeps to its limits). */
  public boolean resetCalib() {
    return send(DpptuText.command("R"));
  }

  /** Stops both axes. */
  public boolean haltAll() {
    return send(DpptuText.command("H"));
  }
}
