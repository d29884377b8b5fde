package org.jaria.laser;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import org.jaria.util.ArArgumentParser;

/**
 * Everything needed to build and connect one laser: its type, port, mounting and set-up choices.
 * Filled from a robot's parameter keys ({@link #fromParams}: {@code LaserType}, {@code
 * LaserPortType}, {@code LaserPort}, {@code LaserAutoConnect}, {@code LaserFlipped}, {@code
 * LaserX/Y/Th}, {@code LaserMaxRange}, {@code LaserDegreesChoice}, {@code LaserIncrementChoice},
 * {@code LaserUnitsChoice}, {@code LaserReflectorBitsChoice}, {@code LaserStartingBaudChoice},
 * {@code LaserAutoBaudChoice}, {@code LaserStartDegrees}, {@code LaserEndDegrees}), then overridden
 * by ARIA's command-line options ({@link #argsAsKeys}, {@link #fromParamsAndArgs}). Empty texts
 * mean "the type's default".
 *
 * @param type "lms2xx" (also "sick"), "urg" or "urg2.0"; "" for none
 * @param portType "serial" or "tcp"
 * @param port a serial device, or HOST:PORT for tcp
 * @param connect whether to connect the laser when the robot connects
 * @param flipped whether it is mounted upside down
 * @param x mounting x, mm
 * @param y mounting y, mm
 * @param th mounting angle, degrees
 * @param maxRange maximum range to use, mm (0: the device's)
 * @param degrees LMS field of view choice ("180" or "100")
 * @param increment LMS increment choice ("one", "half", "quarter", or a number of degrees)
 * @param units LMS units choice ("1mm", "1cm", "10cm")
 * @param reflectorBits LMS reflector bits choice ("1ref", "2ref", "3ref", or a number)
 * @param startingBaud the rate the device talks at now
 * @param autoBaud the rate to switch it to
 * @param startDegrees URG first angle ("" for −90)
 * @param endDegrees URG last angle ("" for 90)
 */
public record LaserOptions(
    String type,
    String portType,
    String port,
    boolean connect,
    boolean flipped,
    double x,
    double y,
    double th,
    double maxRange,
    String degrees,
    String increment,
    String units,
    String reflectorBits,
    String startingBaud,
    String autoBaud,
    String startDegrees,
    String endDegrees) {

  /** No laser. */
  public static final LaserOptions NONE =
      new LaserOptions("", "serial", "", false, false, 0, 0, 0, 0, "", "", "", "", "", "", "", "");

  /** The options a robot's parameters give (keys missing: {@link #NONE}'s values). */
  public static LaserOptions fromParams(Function<String, Optional<String>> raw) {
    Function<String, String> s = k -> raw.apply(k).map(String::strip).orElse("");
    return new LaserOptions(
        s.apply("LaserType"),
        or(s.apply("LaserPortType"), "serial"),
        s.apply("LaserPort"),
        bool(s.apply("LaserAutoConnect"), "LaserAutoConnect"),
        bool(s.apply("LaserFlipped"), "LaserFlipped"),
        number(s.apply("LaserX"), "LaserX"),
        number(s.apply("LaserY"), "LaserY"),
        number(s.apply("LaserTh"), "LaserTh"),
        number(s.apply("LaserMaxRange"), "LaserMaxRange"),
        s.apply("LaserDegreesChoice"),
        s.apply("LaserIncrementChoice"),
        s.apply("LaserUnitsChoice"),
        s.apply("LaserReflectorBitsChoice"),
        s.apply("LaserStartingBaudChoice"),
        s.apply("LaserAutoBaudChoice"),
        s.apply("LaserStartDegrees"),
        s.apply("LaserEndDegrees"));
  }

  /**
   * ARIA's laser options in {@code p}, each consumed, as the parameter keys they override: {@code
   * -laserType|-lt} (LaserType), {@code -laserPortType|-lpt}, {@code -laserPort|-lp}, {@code
   * -laserFlipped|-lf <true|false>}, {@code -laserMaxRange|-lmr}, {@code -laserDegrees|-ld}, {@code
   * -laserDegreesStart|-lds}, {@code -laserDegreesEnd|-lde}, {@code -laserIncrement|-li}, {@code
   * -laserUnits|-lu}, {@code -laserReflectorBits|-lrb}, {@code -laserStartingBaud|-lsb}, {@code
   * -laserAutoBaud|-lab} (also {@code -laserBaud}), {@code -laserAutoConnect <true|false>}, {@code
   * -connectLaser|-cl} and {@code -doNotConnectLaser|-dncl}.
   *
   * @throws IllegalArgumentException if an option lacks its value
   */
  public static Map<String, String> argsAsKeys(ArArgumentParser p) {
    Map<String, String> m = new LinkedHashMap<>();
    put(m, "LaserType", p.checkParameterArgument("-laserType", "-lt"));
    put(m, "LaserPortType", p.checkParameterArgument("-laserPortType", "-lpt"));
    put(m, "LaserPort", p.checkParameterArgument("-laserPort", "-lp"));
    put(m, "LaserFlipped", p.checkParameterArgument("-laserFlipped", "-lf"));
    put(m, "LaserMaxRange", p.checkParameterArgument("-laserMaxRange", "-lmr"));
    put(m, "LaserDegreesChoice", p.checkParameterArgument("-laserDegrees", "-ld"));
    put(m, "LaserStartDegrees", p.checkParameterArgument("-laserDegreesStart", "-lds"));
    put(m, "LaserEndDegrees", p.checkParameterArgument("-laserDegreesEnd", "-lde"));
    put(m, "LaserIncrementChoice", p.checkParameterArgument("-laserIncrement", "-li"));
    put(m, "LaserUnitsChoice", p.checkParameterArgument("-laserUnits", "-lu"));
    put(m, "LaserReflectorBitsChoice", p.checkParameterArgument("-laserReflectorBits", "-lrb"));
    put(m, "LaserStartingBaudChoice", p.checkParameterArgument("-laserStartingBaud", "-lsb"));
    put(m, "LaserAutoBaudChoice", p.checkParameterArgument("-laserAutoBaud", "-lab", "-laserBaud"));
    put(m, "LaserAutoConnect", p.checkParameterArgument("-laserAutoConnect"));
    if (p.checkArgument("-connectLaser", "-cl")) {
      m.put("LaserAutoConnect", "true");
    }
    if (p.checkArgument("-doNotConnectLaser", "-dncl")) {
      m.put("LaserAutoConnect", "false");
    }
    return m;
  }

  private static void put(Map<String, String> m, String key, String value) {
    if (value != null) {
      m.put(key, value);
    }
  }

  /** Parameter keys with command-line overrides on top ({@code args} from {@link #argsAsKeys}). */
  public static LaserOptions fromParamsAndArgs(
      Function<String, Optional<String>> raw, Map<String, String> args) {
    Map<String, String> lower = new HashMap<>();
    args.forEach((k, v) -> lower.put(k.toLowerCase(Locale.ROOT), v));
    return fromParams(
        k -> {
          String v = lower.get(k.toLowerCase(Locale.ROOT));
          return v != null ? Optional.of(v) : raw.apply(k);
        });
  }

  /** ARIA's help text for these options. */
  public static String help() {
    return String.join(
        System.lineSeparator(),
        "Laser options:",
        "  -laserType, -lt <lms2xx|urg|urg2.0>    type of laser",
        "  -laserPort, -lp <port>                 serial device, or HOST:PORT with -lpt tcp",
        "  -laserPortType, -lpt <serial|tcp>      kind of port (default serial)",
        "  -connectLaser, -cl                     connect the laser",
        "  -doNotConnectLaser, -dncl              do not connect it",
        "  -laserAutoConnect <true|false>         connect it (as the LaserAutoConnect key)",
        "  -laserFlipped, -lf <true|false>        mounted upside down",
        "  -laserMaxRange, -lmr <mm>              shorten the maximum range",
        "  -laserDegrees, -ld <180|100>           LMS field of view",
        "  -laserIncrement, -li <one|half|quarter> LMS angle between readings",
        "  -laserUnits, -lu <1mm|1cm|10cm>        LMS distance unit",
        "  -laserReflectorBits, -lrb <1ref|2ref|3ref> LMS reflectance bits",
        "  -laserDegreesStart, -lds <deg>         URG first angle",
        "  -laserDegreesEnd, -lde <deg>           URG last angle",
        "  -laserStartingBaud, -lsb <baud>        rate the laser talks at now",
        "  -laserAutoBaud, -lab, -laserBaud <baud> rate to switch it to");
  }

  /** The type, normalised ("sick" is "lms2xx"; "urg2.0" is "urg"). */
  public String normalType() {
    String t = type.toLowerCase(Locale.ROOT);
    return switch (t) {
      case "sick", "lms200", "lms2xx" -> "lms2xx";
      case "urg", "urg2.0" -> "urg";
      default -> t;
    };
  }

  /**
   * The LMS settings these options choose.
   *
   * @throws IllegalArgumentException if a choice is not one the LMS offers
   */
  public LmsSettings lmsSettings() {
    LmsSettings d = LmsSettings.DEFAULT;
    int deg = degrees.isEmpty() ? d.degrees() : (int) number(degrees, "-laserDegrees");
    double inc =
        switch (increment.toLowerCase(Locale.ROOT)) {
          case "" -> d.increment();
          case "one" -> 1;
          case "half" -> 0.5;
          case "quarter" -> 0.25;
          default -> number(increment, "-laserIncrement");
        };
    String u = units.isEmpty() ? d.units() : units;
    int bits =
        reflectorBits.isEmpty()
            ? d.reflectorBits()
            : (int) number(reflectorBits.toLowerCase(Locale.ROOT).replace("ref", ""), "-lrb");
    int baud = autoBaud.isEmpty() ? d.baud() : (int) number(autoBaud, "-laserAutoBaud");
    return new LmsSettings(deg, inc, u, bits, baud);
  }

  /** The URG settings these options choose. */
  public UrgSettings urgSettings() {
    UrgSettings d = UrgSettings.DEFAULT;
    double s = startDegrees.isEmpty() ? d.startDeg() : number(startDegrees, "-laserDegreesStart");
    double e = endDegrees.isEmpty() ? d.endDeg() : number(endDegrees, "-laserDegreesEnd");
    int sb = startingBaud.isEmpty() ? d.startingBaud() : (int) number(startingBaud, "-lsb");
    int ab = autoBaud.isEmpty() ? sb : (int) number(autoBaud, "-laserAutoBaud");
    return new UrgSettings(s, e, 1, sb, ab);
  }

  private static String or(String s, String fallback) {
    return s.isEmpty() ? fallback : s.toLowerCase(Locale.ROOT);
  }

  private static boolean bool(String s, String what) {
    return switch (s.toLowerCase(Locale.ROOT)) {
      case "", "false", "0" -> false;
      case "true", "1" -> true;
      default -> throw new IllegalArgumentException(what + " is true or false, not '" + s + "'");
    };
  }

  private static double number(String s, String what) {
    if (s.isEmpty()) {
      return 0;
    }
    try {
      return Double.parseDouble(s);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(what + " must be a number, not '" + s + "'", e);
    }
  }
}
