package org.jaria.acts.testing;

import java.util.SplittableRandom;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.image.RgbImage;

/** Small pictures and channel banks for tests. */
public final class Pictures {

  /** Pure red. */
  public static final int RED = 0xFF0000;

  /** Pure green. */
  public static final int GREEN = 0x00FF00;

  /** Pure blue. */
  public static final int BLUE = 0x0000FF;

  /** Yellow: wanted by both the red-ish and the green-ish channel of {@link #rgbBank()}. */
  public static final int YELLOW = 0xFFFF00;

  private Pictures() {}

  /**
   * A picture drawn in characters, one string per row: {@code R} red, {@code G} green, {@code B}
   * blue, {@code Y} yellow, anything else black.
   */
  public static RgbImage draw(String... rows) {
    int h = rows.length;
    int w = rows[0].length();
    RgbImage img = new RgbImage(w, h);
    for (int y = 0; y < h; y++) {
      if (rows[y].length() != w) {
        throw new IllegalArgumentException("row " + y + " has a different length");
      }
      for (int x = 0; x < w; x++) {
        img.set(
            x,
            y,
            switch (rows[y].charAt(x)) {
              case 'R' -> RED;
              case 'G' -> GREEN;
              case 'B' -> BLUE;
              case 'Y' -> YELLOW;
              default -> 0;
            });
      }
    }
    return img;
  }

  /**
   * Channel 1 wants red and yellow (R &ge; 128, B &lt; 128), channel 2 green and yellow (G &ge;
   * 128, B &lt; 128), channel 3 blue (B &ge; 128, R and G &lt; 128); every channel tracks 10 blobs.
   */
  public static ChannelBank rgbBank() {
    ChannelBank bank = new ChannelBank();
    box(bank, 1, 128, 255, 0, 255, 0, 127);
    box(bank, 2, 0, 255, 128, 255, 0, 127);
    box(bank, 3, 0, 127, 0, 127, 128, 255);
    for (int c = 1; c <= 3; c++) {
      bank.setTrackedBlobs(c, 10);
    }
    return bank;
  }

  /** Trains channel {@code ch} with an RGB box. */
  public static void box(ChannelBank bank, int ch, int r0, int r1, int g0, int g1, int b0, int b1) {
    bank.edit(
        ch,
        c -> {
          c.addRgbBox(r0, r1, g0, g1, b0, b1);
          return null;
        });
  }

  /** Random blobs of random colours on black, plus salt noise: many shapes, holes and touches. */
  public static RgbImage randomShapes(int w, int h, long seed) {
    SplittableRandom r = new SplittableRandom(seed);
    int[] px = new int[w * h];
    int shapes = 5 + r.nextInt(40);
    for (int s = 0; s < shapes; s++) {
      int color = r.nextInt(1 << 24);
      int cx = r.nextInt(w);
      int cy = r.nextInt(h);
      int rx = 1 + r.nextInt(Math.max(2, w / 6));
      int ry = 1 + r.nextInt(Math.max(2, h / 6));
      boolean ring = r.nextBoolean();
      for (int y = Math.max(0, cy - ry); y <= Math.min(h - 1, cy + ry); y++) {
        for (int x = Math.max(0, cx - rx); x <= Math.min(w - 1, cx + rx); x++) {
          double d = Math.pow((x - cx) / (double) rx, 2) + Math.pow((y - cy) / (double) ry, 2);
          if (d <= 1 && (!ring || d >= 0.4)) {
            px[y * w + x] = color;
          }
        }
      }
    }
    int salt = r.nextInt(w * h / 4 + 1);
    for (int i = 0; i < salt; i++) {
      px[r.nextInt(px.length)] = r.nextInt(1 << 24);
    }
    return new RgbImage(w, h, px);
  }

  /** Uniformly random pixels. */
  public static RgbImage noise(int w, int h, long seed) {
    SplittableRandom r = new SplittableRandom(seed);
    int[] px = new int[w * h];
    for (int i = 0; i < px.length; i++) {
      px[i] = r.nextInt(1 << 24);
    }
    return new RgbImage(w, h, px);
  }
}
