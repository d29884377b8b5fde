package org.jaria.net.data;

import java.util.Objects;

/**
 * How a client should draw one figure on the map (ArNetworking's {@code ArDrawingData}): the shape,
 * colours, size and layer; the figure's points come separately, from the data named after the
 * drawing. MobileEyes knows the shapes {@code polyDots} (filled circles {@code size} mm across),
 * {@code polyArrows} (arrows {@code size} mm long pointing at the robot), {@code polyLine} (a line
 * through the points, {@code size} pixels wide), {@code polyPoints} (one-pixel points) and {@code
 * polySegments} (a segment from each even point to the next).
 *
 * @param shape one of the shapes above
 * @param primaryColor the colour as 0RGB ({@code 0xFF0000} is red)
 * @param size the size, meaning depends on the shape
 * @param layer the layer, above 30 and below 100 (the robot is drawn on 50; range devices from 70)
 * @param defaultRefreshTime how often a client should ask for the points, ms (0: only when sent)
 * @param secondaryColor a second colour (no shape uses it yet), 0RGB
 * @param visibility {@code AlwaysOn}, {@code DefaultOn}, {@code DefaultOff} or {@code AlwaysOff}
 */
public record ArDrawingData(
    String shape,
    int primaryColor,
    int size,
    int layer,
    long defaultRefreshTime,
    int secondaryColor,
    String visibility) {

  /** ArNetworking's default refresh time, ms. */
  public static final long DEFAULT_REFRESH_TIME = 200;

  /** Checks the texts and the refresh time (which travels as an unsigned 4-byte number). */
  public ArDrawingData {
    Objects.requireNonNull(shape, "shape");
    Objects.requireNonNull(visibility, "visibility");
    if (defaultRefreshTime < 0 || defaultRefreshTime > 0xFFFF_FFFFL) {
      throw new IllegalArgumentException(
          "a refresh time is 0..4294967295 ms, not " + defaultRefreshTime);
    }
  }

  /**
   * A drawing with ArNetworking's defaults: refreshed every 200 ms, black secondary colour, shown
   * by default.
   */
  public static ArDrawingData of(String shape, int primaryColor, int size, int layer) {
    return new ArDrawingData(
        shape, primaryColor, size, layer, DEFAULT_REFRESH_TIME, 0, "DefaultOn");
  }

  /** A colour as ArNetworking's 0RGB number, from 0..255 components. */
  public static int color(int red, int green, int blue) {
    return ((red & 0xFF) << 16) | ((green & 0xFF) << 8) | (blue & 0xFF);
  }
}
