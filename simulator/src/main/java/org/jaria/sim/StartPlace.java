package org.jaria.sim;

import java.util.Locale;
import java.util.random.RandomGenerator;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.world.WorldMap;

/**
 * MobileSim's {@code --start}: where robots start instead of the map's home. A fixed pose ({@code
 * x,y,th} in mm and degrees), {@code outside} (2 m left of the map's bounds, level with its top, at
 * heading 0: a client must move them in with SIM_SET_POSE), or {@code random} (anywhere within the
 * map's bounds, from the world's seed; a spot that touches something is moved aside as every start
 * is). As in MobileSim it applies to every robot: with a fixed pose or {@code outside} the robots
 * stand in a row, each one metre below (−y) the one before; with {@code random} each gets its own
 * spot.
 *
 * @param kind which of the three
 * @param pose the fixed pose (only for {@link Kind#FIXED})
 */
public record StartPlace(Kind kind, ArPose pose) {

  /** The forms {@code --start} takes. */
  public enum Kind {
    /** {@code x,y,th}. */
    FIXED,
    /** {@code outside}. */
    OUTSIDE,
    /** {@code random}. */
    RANDOM
  }

  /** Distance beyond the map's bounds of an {@code outside} start, mm. */
  public static final double OUTSIDE_MARGIN = 2000;

  /** Distance between two robots of MobileSim's row, mm (each below the one before). */
  public static final double ROW_SPACING = 1000;

  /**
   * Reads a {@code --start} value.
   *
   * @throws IllegalArgumentException saying the three forms if {@code s} is none of them
   */
  public static StartPlace parse(String s) {
    String v = s.trim().toLowerCase(Locale.ROOT);
    if (v.equals("outside")) {
      return new StartPlace(Kind.OUTSIDE, null);
    }
    if (v.equals("random")) {
      return new StartPlace(Kind.RANDOM, null);
    }
    String[] p = v.split(",", -1);
    if (p.length == 3) {
      try {
        return new StartPlace(
            Kind.FIXED,
            new ArPose(
                Long.parseLong(p[0].trim()),
                Long.parseLong(p[1].trim()),
                Integer.parseInt(p[2].trim())));
      } catch (NumberFormatException e) {
        // fall through to the explanation
      }
    }
    throw new IllegalArgumentException(
        "--start takes x,y,th (whole mm and degrees, e.g. 200,4650,90), outside or random; got '"
            + s
            + "'");
  }

  /** The start pose of robot number {@code index} (0 first) in {@code map}. */
  public ArPose poseFor(int index, WorldMap map, RandomGenerator rng) {
    return switch (kind) {
      case FIXED -> inRow(pose, index);
      case OUTSIDE -> {
        double[] b = bounds(map);
        yield inRow(new ArPose(b[0] - OUTSIDE_MARGIN, b[3], 0), index);
      }
      case RANDOM -> {
        double[] b = bounds(map);
        yield new ArPose(
            b[0] + rng.nextDouble() * (b[2] - b[0]),
            b[1] + rng.nextDouble() * (b[3] - b[1]),
            rng.nextDouble() * 360 - 180);
      }
    };
  }

  /** Where robot {@code index} of MobileSim's row starting at {@code first} stands. */
  public static ArPose inRow(ArPose first, int index) {
    return index == 0 ? first : new ArPose(first.x(), first.y() - ROW_SPACING * index, first.th());
  }

  /** minX, minY, maxX, maxY of the map's lines and points (a 10 m square at the origin if none). */
  static double[] bounds(WorldMap map) {
    double minX = Double.POSITIVE_INFINITY;
    double minY = Double.POSITIVE_INFINITY;
    double maxX = Double.NEGATIVE_INFINITY;
    double maxY = Double.NEGATIVE_INFINITY;
    for (ArLineSegment l : map.lines()) {
      minX = Math.min(minX, Math.min(l.x1(), l.x2()));
      maxX = Math.max(maxX, Math.max(l.x1(), l.x2()));
      minY = Math.min(minY, Math.min(l.y1(), l.y2()));
      maxY = Math.max(maxY, Math.max(l.y1(), l.y2()));
    }
    int[] px = map.pointX();
    int[] py = map.pointY();
    for (int i = 0; i < px.length; i++) {
      minX = Math.min(minX, px[i]);
      maxX = Math.max(maxX, px[i]);
      minY = Math.min(minY, py[i]);
      maxY = Math.max(maxY, py[i]);
    }
    if (minX > maxX) {
      return new double[] {-5000, -5000, 5000, 5000};
    }
    return new double[] {minX, minY, maxX, maxY};
  }
}
