package org.jaria.sim.serial;

/**
 * An aux-port device that points something: a pan-tilt(-zoom) camera or unit. The simulated camera
 * can follow it, so a program that pans the real device over the wire sees its camera's view turn.
 */
public interface PtzHead {

  /**
   * Where the head points now.
   *
   * @param panRightDeg pan, degrees, positive to the right (ARIA's {@code ArPTZ} convention)
   * @param tiltUpDeg tilt, degrees, positive up
   * @param zoomFraction zoom, 0 (widest) .. 1 (most telephoto); 0 for a unit that does not zoom
   */
  record Pointing(double panRightDeg, double tiltUpDeg, double zoomFraction) {}

  /** Where the head points now. */
  Pointing pointing();
}
