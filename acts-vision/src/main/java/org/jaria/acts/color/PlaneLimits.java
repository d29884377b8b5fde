package org.jaria.acts.color;

/**
 * The manual-training limits of one colour plane (thesis §5.3.16): two colour thresholds and the
 * High Bright / Low Bright limits. Limits mask the trained cells without erasing them, so moving a
 * slider back (or {@link Channel#resetLimits() Reset Limits}) brings the colours back.
 *
 * <p>A plane cell whose colour values are {@code (a, b)} (first and second colour, 0..255) is
 * allowed when all of these hold:
 *
 * <ul>
 *   <li>its angle {@code atan2(b, a)} in degrees (0 = pure first colour, 90 = pure second colour;
 *       the black corner counts as 45) is at least {@code firstColor} and at most {@code 90 -
 *       secondColor}: the first-colour slider removes cells sweeping counter-clockwise from the
 *       first colour's axis, the second-colour slider sweeps clockwise from the other axis;
 *   <li>its brightness {@code a + b} (0..510) is at least {@code lowBright} (Low Bright removes the
 *       dark, bottom-left corner) and at most {@code highBright} (High Bright removes the bright,
 *       top-right corner).
 * </ul>
 *
 * @param firstColor degrees removed next to the first colour's axis, 0..90
 * @param secondColor degrees removed next to the second colour's axis, 0..90
 * @param lowBright smallest allowed {@code a + b}, 0..510
 * @param highBright largest allowed {@code a + b}, 0..510
 */
public record PlaneLimits(int firstColor, int secondColor, int lowBright, int highBright) {

  /** Largest brightness {@code a + b}. */
  public static final int MAX_BRIGHT = 510;

  /** No limits: every trained cell is used. */
  public static final PlaneLimits NONE = new PlaneLimits(0, 0, 0, MAX_BRIGHT);

  /** Checks the ranges. */
  public PlaneLimits {
    check("firstColor", firstColor, 90);
    check("secondColor", secondColor, 90);
    check("lowBright", lowBright, MAX_BRIGHT);
    check("highBright", highBright, MAX_BRIGHT);
  }

  private static void check(String name, int value, int max) {
    if (value < 0 || value > max) {
      throw new IllegalArgumentException(name + " must be between 0 and " + max + ", got " + value);
    }
  }

  /** Whether these are the default, no-limit settings. */
  public boolean isNone() {
    return equals(NONE);
  }

  /** These limits with new colour thresholds. */
  public PlaneLimits withColor(int first, int second) {
    return new PlaneLimits(first, second, lowBright, highBright);
  }

  /** These limits with new brightness limits. */
  public PlaneLimits withBright(int low, int high) {
    return new PlaneLimits(firstColor, secondColor, low, high);
  }

  /** Whether a cell whose colour values are {@code (a, b)} passes these limits. */
  public boolean allows(int a, int b) {
    int sum = a + b;
    if (sum < lowBright || sum > highBright) {
      return false;
    }
    if (firstColor == 0 && secondColor == 0) {
      return true;
    }
    double angle = (a == 0 && b == 0) ? 45.0 : Math.toDegrees(Math.atan2(b, a));
    return angle >= firstColor && angle <= 90 - secondColor;
  }
}
