package org.jaria.tools.options;

import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The one meaning of {@code --seconds} in every command that has it ({@code sim}, {@code demo} and
 * its programs, {@code demo guiserver}): how long to run, 0 for no limit (until Ctrl-C), never
 * negative. Give a field {@code converter = SecondsOption.Whole.class} (or {@code Fractional}).
 */
public final class SecondsOption {

  private SecondsOption() {}

  /**
   * {@code text} as a number of seconds.
   *
   * @throws TypeConversionException if it is not a number, or is negative, with what to give
   */
  static double parse(String text) {
    double s;
    try {
      s = Double.parseDouble(text.strip());
    } catch (NumberFormatException e) {
      throw new TypeConversionException(
          "'" + text + "' is not a number of seconds: give e.g. 60, or 0 for no limit");
    }
    if (!(s >= 0) || Double.isInfinite(s)) {
      throw new TypeConversionException(
          String.format(
              Locale.ROOT,
              "%s is not a time to run: give the seconds (e.g. 60), or 0 for no limit",
              text.strip()));
    }
    return s;
  }

  /** Whole seconds (the demos). */
  public static final class Whole implements ITypeConverter<Integer> {
    @Override
    public Integer convert(String value) {
      double s = parse(value);
      if (s != Math.rint(s) || s > Integer.MAX_VALUE) {
        throw new TypeConversionException(
            "'" + value + "' is not a whole number of seconds: give e.g. 60, or 0 for no limit");
      }
      return (int) s;
    }
  }

  /** Seconds with a fraction (the simulator's simulated time). */
  public static final class Fractional implements ITypeConverter<Double> {
    @Override
    public Double convert(String value) {
      return parse(value);
    }
  }
}
