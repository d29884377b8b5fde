package org.jaria.apps.eztrain;

import java.util.Locale;

/**
 * How the training window shows the selected channel (thesis §5.3.21.1). Keys 1–4 select a mode
 * while the mouse is over the image; a right click cycles through them.
 */
public enum ViewMode {
  /** The image with the channel's pixels painted in the thresh colour (key 1). */
  OVERLAY("Overlay"),
  /** The channel's pixels white, the rest black, blobs boxed in purple (key 2). */
  THRESH("Thresh"),
  /** The image as it is (key 3). */
  RAW("Raw"),
  /** Only the channel's pixels, in their own colours (key 4). */
  VISIBLE("Visible");

  private final String label;

  ViewMode(String label) {
    this.label = label;
  }

  /** The name in menus. */
  public String label() {
    return label;
  }

  /** The key that selects this mode ('1'..'4'). */
  public char key() {
    return (char) ('1' + ordinal());
  }

  /** The next mode, as a right click cycles. */
  public ViewMode next() {
    ViewMode[] all = values();
    return all[(ordinal() + 1) % all.length];
  }

  /** The mode named {@code s} ("thresh", "2"...), ignoring case. */
  public static ViewMode parse(String s) {
    String t = s.trim().toUpperCase(Locale.ROOT);
    for (ViewMode m : values()) {
      if (m.name().equals(t) || String.valueOf(m.key()).equals(t)) {
        return m;
      }
    }
    throw new IllegalArgumentException(
        "no view mode '" + s + "'; use overlay, thresh, raw or visible (or 1-4)");
  }
}
