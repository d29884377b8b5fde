package org.jaria.apps.fx;

import org.jaria.acts.image.RgbImage;

/** Looking at pictures in tests. */
public final class TestImages {

  private TestImages() {}

  /** The bounding box {x0, y0, x1, y1} of the image's clearly red pixels, or null if none. */
  public static int[] redBox(RgbImage f) {
    int[] b = {Integer.MAX_VALUE, Integer.MAX_VALUE, -1, -1};
    for (int y = 0; y < f.height(); y++) {
      for (int x = 0; x < f.width(); x++) {
        int p = f.get(x, y);
        int r = (p >> 16) & 0xFF;
        int g = (p >> 8) & 0xFF;
        int bl = p & 0xFF;
        if (r > 90 && r > 2 * g && r > 2 * bl) {
          b[0] = Math.min(b[0], x);
          b[1] = Math.min(b[1], y);
          b[2] = Math.max(b[2], x);
          b[3] = Math.max(b[3], y);
        }
      }
    }
    return b[2] < 0 ? null : b;
  }
}
