package org.jaria.net.provider;

/**
 * A pan-tilt-zoom camera the network server lets clients point (ARIA's {@code ArPTZ}, as {@code
 * ArServerHandlerCamera} uses it). Angles are degrees with ARIA's signs: pan positive to the right,
 * tilt positive up; zoom is in the unit's own steps from {@link #getMinZoom()} to {@link
 * #getMaxZoom()}. Requests outside the limits are clamped by the unit. The getters may report the
 * last position asked for (a unit that cannot say where it points). Called from the server's
 * threads and the robot's cycle: implementations must be thread-safe.
 */
public interface PtzControl {

  /** The unit's type, for clients ("VCC4"). */
  String getTypeName();

  /** Pans and tilts to absolute angles, degrees. */
  boolean panTilt(double panDegrees, double tiltDegrees);

  /** Zooms to an absolute position (ignored by a unit that cannot zoom). */
  boolean zoom(int value);

  /** Current (or last requested) pan, degrees. */
  double getPan();

  /** Current (or last requested) tilt, degrees. */
  double getTilt();

  /** Current (or last requested) zoom position. */
  int getZoom();

  /** Whether the unit zooms. */
  boolean canZoom();

  /** Largest pan to the right, degrees. */
  double getMaxPosPan();

  /** Largest pan to the left, degrees (negative). */
  double getMaxNegPan();

  /** Largest tilt up, degrees. */
  double getMaxPosTilt();

  /** Largest tilt down, degrees (negative). */
  double getMaxNegTilt();

  /** Smallest zoom position. */
  int getMinZoom();

  /** Largest zoom position. */
  int getMaxZoom();

  /** Points the unit home (0, 0, smallest zoom), re-initialising it if it needs that. */
  default boolean reset() {
    boolean ok = panTilt(0, 0);
    return zoom(getMinZoom()) && ok;
  }
}
