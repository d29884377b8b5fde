package org.jaria.apps.eztrain;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jaria.acts.blob.Blob;

/** The texts EZ-Train prints in its output area and help: blob stats, timing, keys and mouse. */
final class EzTrainInfo {

  private EzTrainInfo() {}

  /** Info → Blob stats: the channel's tracked blobs, one line each. */
  static String blobStats(Rendered r, int tracking) {
    StringBuilder b = new StringBuilder();
    b.append(
        String.format(
            Locale.ROOT,
            "Channel %d: %d blob(s) (tracking up to %d)",
            r.channel(),
            r.blobs().size(),
            tracking));
    int n = 1;
    for (Blob blob : r.blobs()) {
      b.append(
          String.format(
              Locale.ROOT,
              "%n  %d: a %d  x %d  y %d  left %d  right %d  top %d  bottom %d",
              n++,
              blob.area(),
              blob.xcg(),
              blob.ycg(),
              blob.left(),
              blob.right(),
              blob.top(),
              blob.bottom()));
    }
    return b.toString();
  }

  /**
   * Info → Timing: tracking time per frame and the frame rates.
   *
   * @param videoFps the live video's frame rate, NaN without video
   * @param serverTiming the ACTS server's own figures
   */
  static String timing(Rendered r, double videoFps, String serverTiming) {
    double ms = r.trackNanos() / 1e6;
    StringBuilder b =
        new StringBuilder(
            String.format(
                Locale.ROOT,
                "Tracking a %dx%d frame (32 channels) took %.2f ms (up to %.0f frames/s)",
                r.frame().width(),
                r.frame().height(),
                ms,
                ms > 0 ? 1000 / ms : 0));
    if (!Double.isNaN(videoFps)) {
      b.append(String.format(Locale.ROOT, "; video %.1f frames/s", videoFps));
    }
    return b.append("; ").append(serverTiming).toString();
  }

  /** Help → Keyboard Shortcuts: the keys and mouse actions (the menus' shortcuts follow). */
  static List<String> keysAndMouse() {
    List<String> intro = new ArrayList<>();
    intro.add("Keys (not while typing in a field)");
    for (ViewMode m : ViewMode.values()) {
      intro.add(String.format(Locale.ROOT, "  %-18s %s view", m.key(), m.label()));
    }
    for (TrainTool t : TrainTool.values()) {
      intro.add(String.format(Locale.ROOT, "  %-18s %s tool", t.key().getName(), t.label()));
    }
    intro.add("  Esc                cancel a drag, or quit");
    intro.add("");
    intro.add("Mouse on the image");
    intro.add("  Left drag          Add/Remove: a rectangle; Draw/Erase: a brush stroke");
    intro.add("  Left click         Pick: print the pixel's color");
    intro.add("  Right click        next view mode");
    intro.add("  Middle click       grab a frame (single-frame video)");
    return intro;
  }
}
