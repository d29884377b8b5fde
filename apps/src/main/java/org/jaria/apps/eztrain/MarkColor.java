package org.jaria.apps.eztrain;

/** The colours EZ-Train offers for the thresh overlay and the drawing rectangle. */
public enum MarkColor {
  /** Red. */
  RED("Red", 0xFF2020),
  /** Green. */
  GREEN("Green", 0x20E020),
  /** Blue (the thresh default). */
  BLUE("Blue", 0x2040FF);

  private final String label;
  private final int rgb;

  MarkColor(String label, int rgb) {
    this.label = label;
    this.rgb = rgb;
  }

  /** The name in menus. */
  public String label() {
    return label;
  }

  /** Packed {@code 0xRRGGBB}. */
  public int rgb() {
    return rgb;
  }
}
