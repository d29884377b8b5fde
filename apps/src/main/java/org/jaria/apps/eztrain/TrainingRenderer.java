package org.jaria.apps.eztrain;

import org.jaria.acts.blob.Blob;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.image.RgbImage;

/**
 * Turns a frame, the compiled channels and the tracked blobs into the pixels the training window
 * shows in each {@link ViewMode}, and a channel's colour planes into the manual-training images.
 * Pure functions on arrays, usable on any thread.
 */
public final class TrainingRenderer {

  /** ACTS's purple for blob boxes and centroids in Thresh mode. */
  public static final int BLOB_PURPLE = 0xC020C0;

  private TrainingRenderer() {}

  /**
   * The training image as ARGB pixels, the frame's size.
   *
   * @param channel the selected channel (1..32)
   * @param blobs the channel's tracked blobs (boxed in Thresh mode), or null
   * @param threshRgb the overlay colour, packed RGB
   */
  public static int[] render(
      RgbImage frame,
      LookupTables tables,
      int channel,
      BlobFrame blobs,
      ViewMode mode,
      int threshRgb) {
    int[] px = frame.pixels();
    int[] out = new int[px.length];
    int bit = 1 << (channel - 1);
    for (int i = 0; i < px.length; i++) {
      int p = px[i] & 0xFFFFFF;
      boolean in = mode != ViewMode.RAW && (tables.classify(p) & bit) != 0;
      int c =
          switch (mode) {
            case OVERLAY -> in ? threshRgb : p;
            case THRESH -> in ? 0xFFFFFF : 0x000000;
            case RAW -> p;
            case VISIBLE -> in ? p : 0x000000;
          };
      out[i] = 0xFF000000 | c;
    }
    if (mode == ViewMode.THRESH && blobs != null) {
      for (int n = 1; n <= blobs.getNumBlobs(channel); n++) {
        box(out, frame.width(), frame.height(), blobs.getBlob(channel, n));
      }
    }
    return out;
  }

  private static void box(int[] out, int w, int h, Blob b) {
    int color = 0xFF000000 | BLOB_PURPLE;
    for (int x = b.left(); x <= b.right(); x++) {
      set(out, w, h, x, b.top(), color);
      set(out, w, h, x, b.bottom(), color);
    }
    for (int y = b.top(); y <= b.bottom(); y++) {
      set(out, w, h, b.left(), y, color);
      set(out, w, h, b.right(), y, color);
    }
    set(out, w, h, b.xcg(), b.ycg(), color);
  }

  private static void set(int[] out, int w, int h, int x, int y, int c) {
    if (x >= 0 && y >= 0 && x < w && y < h) {
      out[y * w + x] = c;
    }
  }

  /**
   * One colour plane of a channel as a square ARGB image, one pixel per cell: the first colour
   * grows to the right, the second upwards (so dark colours are bottom left, bright ones top right,
   * as in ACTS). Trained cells the limits allow are white, trained cells the limits remove dark
   * grey, untrained cells black.
   */
  public static int[] renderPlane(Channel channel, ColorPlane plane) {
    int n = channel.cellsPerAxis();
    int[] out = new int[n * n];
    for (int a = 0; a < n; a++) {
      for (int b = 0; b < n; b++) {
        int c;
        if (!channel.isTrained(plane, a, b)) {
          c = 0xFF000000;
        } else if (channel.isEffective(plane, a, b)) {
          c = 0xFFFFFFFF;
        } else {
          c = 0xFF505050;
        }
        out[(n - 1 - b) * n + a] = c;
      }
    }
    return out;
  }
}
