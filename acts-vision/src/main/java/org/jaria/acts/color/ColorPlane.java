package org.jaria.acts.color;

/**
 * The three two-colour planes a channel is made of (thesis §5.3.14). Instead of one table with an
 * entry for each of the 16.7 million RGB colours, ACTS projects every colour onto three planes: Red
 * against Green, Blue against Green and Red against Blue. A pixel belongs to a channel when its
 * projection is set in all three planes.
 *
 * <p>In each plane the first colour is the horizontal axis ({@code a}) and the second the vertical
 * one ({@code b}); {@link #first(int)} and {@link #second(int)} pick them out of a packed {@code
 * 0xRRGGBB} pixel.
 */
public enum ColorPlane {
  /** Red (a) against Green (b). */
  RG,
  /** Blue (a) against Green (b). */
  BG,
  /** Red (a) against Blue (b). */
  RB;

  private static final ColorPlane[] ALL = values();

  /** The three planes in file and table order (RG, BG, RB). */
  public static ColorPlane[] all() {
    return ALL.clone();
  }

  /** The plane's first colour component (0..255) of a packed {@code 0xRRGGBB} pixel. */
  public int first(int rgb) {
    return switch (this) {
      case RG, RB -> (rgb >>> 16) & 0xFF;
      case BG -> rgb & 0xFF;
    };
  }

  /** The plane's second colour component (0..255) of a packed {@code 0xRRGGBB} pixel. */
  public int second(int rgb) {
    return switch (this) {
      case RG, BG -> (rgb >>> 8) & 0xFF;
      case RB -> rgb & 0xFF;
    };
  }

  /** The name of the first colour ("Red" or "Blue"), for user interfaces. */
  public String firstName() {
    return this == BG ? "Blue" : "Red";
  }

  /** The name of the second colour ("Green" or "Blue"), for user interfaces. */
  public String secondName() {
    return this == RB ? "Blue" : "Green";
  }
}
