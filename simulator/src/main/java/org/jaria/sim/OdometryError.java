package org.jaria.sim;

import java.util.Locale;

/**
 * How the simulated wheel encoders err, so that a robot's odometry drifts away from its true pose
 * the way a real one does. The true pose is never affected; it stays readable through {@link
 * SimRobot#getTruePose()} and SIMSTAT.
 *
 * <ul>
 *   <li>{@link Mode#NONE}: odometry is exact.
 *   <li>{@link Mode#CONSTANT}: a systematic error: every distance travelled is measured {@code
 *       transPerMetre} too long (0.02 = 2 cm per metre) and every turn {@code rotPerRadian} too
 *       large (0.05 = 5 %); negative values measure short.
 *   <li>{@link Mode#RANDOM}: a random walk drawn afresh on every update: after a metre of travel
 *       the distance error has a standard deviation of {@code transPerMetre} metres, after one
 *       radian of turning the heading error has a standard deviation of {@code rotPerRadian}
 *       radians (the variance grows with the distance, as for real wheels).
 * </ul>
 *
 * @param mode which kind of error
 * @param transPerMetre distance error per metre travelled (fraction)
 * @param rotPerRadian heading error per radian turned (fraction)
 */
public record OdometryError(Mode mode, double transPerMetre, double rotPerRadian) {

  /** The kinds of odometry error. */
  public enum Mode {
    /** Perfect odometry. */
    NONE,
    /** A fixed scale error on distance and rotation. */
    CONSTANT,
    /** A random error drawn on every update (seeded). */
    RANDOM,
    /** MobileSim's default: uniform scale errors drawn afresh every 100 ms (seeded). */
    RANDOM_EACH_UPDATE,
    /** MobileSim's {@code random_init}: uniform scale errors drawn once per robot (seeded). */
    RANDOM_INIT
  }

  /**
   * How often {@link Mode#RANDOM_EACH_UPDATE} draws new factors, ms of simulated time: MobileSim's
   * default update interval.
   */
  public static final int UPDATE_MILLIS = 100;

  /** The error bound of MobileSim's robot models ({@code odom_error}), per metre and per radian. */
  public static final double MOBILESIM_ERROR = 0.0075;

  /** No error. */
  public static final OdometryError NONE = new OdometryError(Mode.NONE, 0, 0);

  /** Checks the values. */
  public OdometryError {
    if (mode == null) {
      throw new IllegalArgumentException("odometry error mode must not be null");
    }
    if (!Double.isFinite(transPerMetre) || !Double.isFinite(rotPerRadian)) {
      throw new IllegalArgumentException(
          "odometry error values must be finite numbers, got "
              + transPerMetre
              + ", "
              + rotPerRadian);
    }
    if (mode == Mode.RANDOM && (transPerMetre < 0 || rotPerRadian < 0)) {
      throw new IllegalArgumentException(
          "random odometry error is a standard deviation and cannot be negative");
    }
    if ((mode == Mode.RANDOM_EACH_UPDATE || mode == Mode.RANDOM_INIT)
        && (transPerMetre < 0 || rotPerRadian < 0 || transPerMetre >= 1 || rotPerRadian >= 1)) {
      throw new IllegalArgumentException(
          "MobileSim's random odometry errors are bounds in [0, 1), e.g. 0.0075; got "
              + transPerMetre
              + ", "
              + rotPerRadian);
    }
  }

  /** A systematic error. */
  public static OdometryError constant(double transPerMetre, double rotPerRadian) {
    return new OdometryError(Mode.CONSTANT, transPerMetre, rotPerRadian);
  }

  /** A random-walk error. */
  public static OdometryError random(double transPerMetre, double rotPerRadian) {
    return new OdometryError(Mode.RANDOM, transPerMetre, rotPerRadian);
  }

  /** MobileSim's default error: uniform scale errors within ±T and ±R, drawn every 100 ms. */
  public static OdometryError randomEachUpdate(double transPerMetre, double rotPerRadian) {
    return new OdometryError(Mode.RANDOM_EACH_UPDATE, transPerMetre, rotPerRadian);
  }

  /** MobileSim's {@code random_init}: uniform scale errors within ±T and ±R, drawn once. */
  public static OdometryError randomInit(double transPerMetre, double rotPerRadian) {
    return new OdometryError(Mode.RANDOM_INIT, transPerMetre, rotPerRadian);
  }

  /**
   * MobileSim's {@code --odom-error-mode}: {@code random_each_update}, {@code random_init} or
   * {@code constant} with its models' error of {@value #MOBILESIM_ERROR}, or {@code none}.
   *
   * @throws IllegalArgumentException naming the four modes
   */
  public static OdometryError ofMobileSimMode(String mode) {
    double e = MOBILESIM_ERROR;
    return switch (mode.trim().toLowerCase(Locale.ROOT)) {
      case "random_each_update" -> randomEachUpdate(e, e);
      case "random_init" -> randomInit(e, e);
      case "constant" -> constant(e, e);
      case "none" -> NONE;
      default ->
          throw new IllegalArgumentException(
              "odometry error mode '"
                  + mode
                  + "' not understood: use random_init, random_each_update, constant or none");
    };
  }

  /**
   * Parses the command-line form: {@code none}, {@code constant:T,R}, {@code random:T,R}, {@code
   * random_each_update:T,R} or {@code random_init:T,R} (T per metre, R per radian, e.g. {@code
   * random:0.02,0.05}); {@code random_each_update} and {@code random_init} alone take MobileSim's
   * {@value #MOBILESIM_ERROR}.
   *
   * @throws IllegalArgumentException with a message showing the accepted forms
   */
  public static OdometryError parse(String text) {
    String t = text.trim().toLowerCase(Locale.ROOT);
    if (t.equals("none") || t.equals("random_each_update") || t.equals("random_init")) {
      return ofMobileSimMode(t);
    }
    int colon = t.indexOf(':');
    String usage =
        "odometry error '"
            + text
            + "' not understood: use none, constant:T,R, random:T,R, random_each_update:T,R or"
            + " random_init:T,R (T = error per metre, R = error per radian, e.g."
            + " random:0.02,0.05)";
    if (colon < 0) {
      throw new IllegalArgumentException(usage);
    }
    Mode mode;
    switch (t.substring(0, colon)) {
      case "constant" -> mode = Mode.CONSTANT;
      case "random" -> mode = Mode.RANDOM;
      case "random_each_update" -> mode = Mode.RANDOM_EACH_UPDATE;
      case "random_init" -> mode = Mode.RANDOM_INIT;
      default -> throw new IllegalArgumentException(usage);
    }
    String values = t.substring(colon + 1);
    int comma = values.indexOf(',');
    if (comma < 0 || values.indexOf(',', comma + 1) >= 0) {
      throw new IllegalArgumentException(usage);
    }
    try {
      return new OdometryError(
          mode,
          Double.parseDouble(values.substring(0, comma).trim()),
          Double.parseDouble(values.substring(comma + 1).trim()));
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(usage, e);
    }
  }
}
