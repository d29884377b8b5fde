package org.jaria.acts.testing;

import org.jaria.acts.color.ChannelBank;

/**
 * The trained channels of the desk test scene that the vision benchmark ({@code jaria bench
 * vision}) times and the OpenCV cross-check compares: eight RGB boxes around the scene's objects,
 * and shifted, narrower copies of them for channels 9 to 32. Shared through this module's test jar.
 */
public final class SceneChannels {

  /** The boxes {r0, r1, g0, g1, b0, b1} of the eight base channels. */
  private static final int[][] BASE_BOXES = {
    {110, 255, 0, 70, 0, 80}, // red (book, cup)
    {20, 75, 90, 165, 35, 95}, // green (mug)
    {15, 75, 35, 95, 115, 205}, // blue (pen)
    {195, 255, 175, 245, 35, 105}, // yellow (note)
    {150, 255, 80, 145, 0, 55}, // orange (ball)
    {185, 255, 115, 175, 125, 190}, // pink (eraser)
    {95, 185, 60, 130, 30, 80}, // wood (desk)
    {155, 230, 145, 220, 125, 195}, // wall
  };

  private SceneChannels() {}

  /** The RGB box {r0, r1, g0, g1, b0, b1} of benchmark channel {@code i} (0-based). */
  public static int[] box(int i) {
    int[] b = BASE_BOXES[i % 8].clone();
    int shift = (i / 8) * 6;
    for (int k = 0; k < 6; k += 2) {
      b[k] = Math.max(0, Math.min(250, b[k] + shift));
      b[k + 1] = Math.max(b[k], Math.min(255, b[k + 1] - shift));
    }
    return b;
  }

  /** A bank with the first {@code n} benchmark channels trained, at {@code cellBits}. */
  public static ChannelBank bank(int n, int cellBits) {
    ChannelBank bank = new ChannelBank(cellBits);
    for (int i = 0; i < n; i++) {
      int[] b = box(i);
      bank.edit(
          i + 1,
          c -> {
            c.addRgbBox(b[0], b[1], b[2], b[3], b[4], b[5]);
            return null;
          });
    }
    return bank;
  }
}
