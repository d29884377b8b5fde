package org.jaria.classroom.grading;

import java.util.Locale;

/** Numbers and positions as the grader's messages show them. */
public final class Fmt {

  private Fmt() {}

  /** "(1200, -35)": a position in whole millimetres. */
  public static String xy(double x, double y) {
    return String.format(Locale.ROOT, "(%.0f, %.0f)", x, y);
  }

  /** "1.25 m" or "640 mm": a distance, in the unit easiest to read. */
  public static String dist(double mm) {
    return Math.abs(mm) >= 1000
        ? String.format(Locale.ROOT, "%.2f m", mm / 1000)
        : String.format(Locale.ROOT, "%.0f mm", mm);
  }

  /** "12.3 s". */
  public static String seconds(double s) {
    return String.format(Locale.ROOT, "%.1f s", s);
  }

  /** A number with {@code decimals} decimals, in the root locale. */
  public static String num(double v, int decimals) {
    return String.format(Locale.ROOT, "%." + decimals + "f", v);
  }

  /** "1.5 MB", "800 KB" or "12 bytes": a size, in the unit easiest to read. */
  public static String bytes(long n) {
    if (n >= 1 << 20) {
      return String.format(Locale.ROOT, "%.1f MB", n / (double) (1 << 20));
    }
    return n >= 1 << 10
        ? String.format(Locale.ROOT, "%.0f KB", n / 1024.0)
        : n + (n == 1 ? " byte" : " bytes");
  }
}
