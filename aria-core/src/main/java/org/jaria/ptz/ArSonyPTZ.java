package org.jaria.ptz;

import org.jaria.robot.ArRobot;

/**
 * The Sony EVI-D30/D70 pan-tilt-zoom camera (ARIA's {@code ArSonyPTZ}): ±95° pan, ±25° tilt, zoom
 * 0..1023, over VISCA. 0x370 pan units are 95°, 0x12C tilt units 25°.
 */
public class ArSonyPTZ extends ArPTZ {

  /** Largest pan, degrees. */
  public static final double MAX_PAN = 95;

  /** Largest tilt, degrees. */
  public static final double MAX_TILT = 25;

  /** Largest zoom. */
  public static final int MAX_ZOOM = 1023;

  private static final double DEG_TO_PAN = 0x370 / MAX_PAN;
  private static final double DEG_TO_TILT = 0x12c / MAX_TILT;

  /** A camera on {@code robot}'s AUX1 port. */
  public ArSonyPTZ(ArRobot robot) {
    super(robot);
  }

  @Override
  public boolean init() {
    return send(Visca.init()) && panTilt(0, 0) && zoom(0);
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
  public int getMaxZoom() {
    return MAX_ZOOM;
  }

  @Override
  protected boolean panTiltClamped(double panDeg, double tiltDeg) {
    return send(
        Visca.panTilt(
            (int) Math.round(panDeg * DEG_TO_PAN), (int) Math.round(tiltDeg * DEG_TO_TILT)));
  }

  @Override
  protected boolean zoomClamped(int value) {
    return send(Visca.zoom(value));
  }

  /** Back-lighting compensation on. */
  public boolean backLightingOn() {
    return send(Visca.backLight(true));
  }

  /** Back-lighting compensation off. */
  public boolean backLightingOff() {
    return send(Visca.backLight(false));
  }
}
