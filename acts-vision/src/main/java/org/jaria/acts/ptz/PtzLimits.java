package org.jaria.acts.ptz;

/**
 * The movement limits of a pan-tilt-zoom unit, in degrees and zoom steps.
 *
 * @param maxPosPan largest pan to the left (positive)
 * @param maxNegPan largest pan to the right (negative or zero)
 * @param maxPosTilt largest tilt up (positive)
 * @param maxNegTilt largest tilt down (negative or zero)
 * @param maxZoom largest zoom position
 * @param minZoom smallest zoom position
 */
public record PtzLimits(
    double maxPosPan,
    double maxNegPan,
    double maxPosTilt,
    double maxNegTilt,
    int maxZoom,
    int minZoom) {

  /** Checks that each range is not empty. */
  public PtzLimits {
    if (maxNegPan > maxPosPan || maxNegTilt > maxPosTilt || minZoom > maxZoom) {
      throw new IllegalArgumentException(
          "empty PTZ range: "
              + maxNegPan
              + ".."
              + maxPosPan
              + " pan, "
              + maxNegTilt
              + ".."
              + maxPosTilt
              + " tilt, "
              + minZoom
              + ".."
              + maxZoom
              + " zoom");
    }
  }

  /** A pan angle clamped to the limits. */
  public double clampPan(double degrees) {
    return Math.max(maxNegPan, Math.min(maxPosPan, degrees));
  }

  /** A tilt angle clamped to the limits. */
  public double clampTilt(double degrees) {
    return Math.max(maxNegTilt, Math.min(maxPosTilt, degrees));
  }

  /** A zoom position clamped to the limits. */
  public int clampZoom(int value) {
    return Math.max(minZoom, Math.min(maxZoom, value));
  }
}
