package org.jaria.net.server;

import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.net.protocol.NetError;

/**
 * Checks of numbers that arrive in requests: ArNetworking carries doubles as text, so "nan", "INF"
 * or a pose a kilometre outside the map arrive as easily as good values. Every handler that acts on
 * a number checks it here first and refuses it with a message that says what was wrong.
 */
public final class NumericArgs {

  private NumericArgs() {}

  /** How far outside the map's bounds a pose may lie (mm): the robot may start just outside. */
  public static final double MAP_MARGIN_MM = 1000;

  /**
   * {@code v} if it is a finite number.
   *
   * @throws NetRequestException naming {@code what} otherwise
   */
  public static double finite(double v, String what) throws NetRequestException {
    if (!Double.isFinite(v)) {
      throw new NetRequestException(
          NetError.BAD_ARGUMENTS, what + " must be a finite number, not " + v);
    }
    return v;
  }

  /**
   * {@code v} if it is finite and within {@code min..max}.
   *
   * @throws NetRequestException naming {@code what} and the range otherwise
   */
  public static double within(double v, double min, double max, String what)
      throws NetRequestException {
    finite(v, what);
    if (v < min || v > max) {
      throw new NetRequestException(
          NetError.BAD_ARGUMENTS, what + " must be " + min + ".." + max + ", not " + v);
    }
    return v;
  }

  /**
   * A pose from finite numbers that lies inside {@code map}'s bounds (with {@link #MAP_MARGIN_MM});
   * any finite pose when there is no map or the map is empty.
   *
   * @throws NetRequestException saying which number is wrong or that the pose is off the map
   */
  public static ArPose pose(double x, double y, double th, ArMap map) throws NetRequestException {
    finite(x, "x");
    finite(y, "y");
    finite(th, "th");
    if (map != null) {
      ArPose min = map.getMinPos();
      ArPose max = map.getMaxPos();
      if (min != null
          && max != null
          && max.getX() > min.getX()
          && (x < min.getX() - MAP_MARGIN_MM
              || x > max.getX() + MAP_MARGIN_MM
              || y < min.getY() - MAP_MARGIN_MM
              || y > max.getY() + MAP_MARGIN_MM)) {
        throw new NetRequestException(
            NetError.BAD_ARGUMENTS,
            String.format(
                java.util.Locale.ROOT,
                "(%.0f, %.0f) is outside the map, which spans (%.0f, %.0f) to (%.0f, %.0f)",
                x,
                y,
                min.getX(),
                min.getY(),
                max.getX(),
                max.getY()));
      }
    }
    return new ArPose(x, y, th);
  }
}
