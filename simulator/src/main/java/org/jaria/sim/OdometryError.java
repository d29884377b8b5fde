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
    RANDOM
  }

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
  }

  /** A systematic error. */
  public static OdometryError constant(double transPerMetre, double rotPerRadian) {
    return new OdometryError(Mode.CONSTANT, transPerMetre, rotPerRadian);
  }

  /** A random-walk error. */
  public static OdometryError random(double transPerMetre, double rotPerRadian) {
    return new OdometryError(Mode.RANDOM, transPerMetre, rotPerRadian);
  }

  /**
   * Parses the command-line form: {@code none}, {@code constant:T,R} or {@code random:T,R} (T per
   * metre, R per radian, e.g. {@code random:0.02,0.05}).
   *
   * @throws IllegalArgumentException with a message showing the accepted forms
   */
  public static OdometryError parse(String text) {
    String t = text.trim().toLowerCase(Locale.ROOT);
    if (t.equals("none")) {
      return NONE;
    }
    int colon = t.indexOf(':');
    String usage =
        "odometry error '"
            + text
            + "' not understood: use none, constant:T,R or random:T,R"
            + " (T = error per metre, R = error per radian, e.g. random:0.02,0.05)";
    if (colon < 0) {
      throw new IllegalArgumentException(usage);
    }
    Mode mode;
    switch (t.substring(0, colon)) {
      case "constant" -> mode = Mode.CONSTANT;
      case "random" -> mode = Mode.RANDOM;
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
