package org.jaria.acts.ptz;

/**
 * A pan-tilt-zoom camera unit (ARIA's {@code ArPTZ}), with ARIA's method names. Angles are in
 * degrees: pan positive to the left (counter-clockwise seen from above), tilt positive upwards;
 * zoom in the unit's own steps from {@link #getMinZoom()} to {@link #getMaxZoom()}. Requests
 * outside the limits are clamped to them.
 *
 * <p>Implementations say what their pan/tilt/zoom getters report: usually the last position
 * requested, since many units cannot report their real position.
 */
public interface ArPTZ {

  /** Initialises the unit (power, control mode, homing). */
  boolean init();

  /** Resets the unit; by default the same as {@link #init()}. */
  default boolean reset() {
    return init();
  }

  /** A short type name, e.g. {@code "vcc4"}. */
  String getTypeName();

  /** Pans to an absolute angle. */
  default boolean pan(double degrees) {
    return panTilt(degrees, getTilt());
  }

  /** Pans by an angle relative to the current pan. */
  default boolean panRel(double degrees) {
    return pan(getPan() + degrees);
  }

  /** Tilts to an absolute angle. */
  default boolean tilt(double degrees) {
    return panTilt(getPan(), degrees);
  }

  /** Tilts by an angle relative to the current tilt. */
  default boolean tiltRel(double degrees) {
    return tilt(getTilt() + degrees);
  }

  /** Pans and tilts to absolute angles at once. */
  boolean panTilt(double panDegrees, double tiltDegrees);

  /** Pans and tilts by relative angles at once. */
  default boolean panTiltRel(double panDegrees, double tiltDegrees) {
    return panTilt(getPan() + panDegrees, getTilt() + tiltDegrees);
  }

  /** Whether the unit can zoom. */
  boolean canZoom();

  /** Zooms to an absolute position. */
  boolean zoom(int value);

  /** Zooms by a relative amount. */
  default boolean zoomRel(int amount) {
    return zoom(getZoom() + amount);
  }

  /** Current (or last requested) pan angle. */
  double getPan();

  /** Current (or last requested) tilt angle. */
  double getTilt();

  /** Current (or last requested) zoom position. */
  int getZoom();

  /** The unit's limits. */
  PtzLimits getLimits();

  /** Largest pan angle to the left. */
  default double getMaxPosPan() {
    return getLimits().maxPosPan();
  }

  /** Largest pan angle to the right (negative). */
  default double getMaxNegPan() {
    return getLimits().maxNegPan();
  }

  /** Largest upward tilt. */
  default double getMaxPosTilt() {
    return getLimits().maxPosTilt();
  }

  /** Largest downward tilt (negative). */
  default double getMaxNegTilt() {
    return getLimits().maxNegTilt();
  }

  /** Largest zoom position. */
  default int getMaxZoom() {
    return getLimits().maxZoom();
  }

  /** Smallest zoom position. */
  default int getMinZoom() {
    return getLimits().minZoom();
  }

  /** Switches the unit's power; returns false if the unit cannot. */
  default boolean power(boolean on) {
    return false;
  }
}
