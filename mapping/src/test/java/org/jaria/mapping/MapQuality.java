package org.jaria.mapping;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapPoints;

/**
 * How well a built map and path agree with the truth: the path's error against the true laser poses
 * (the built frame placed on the true one by the first pose, as the builder keeps the log's frame),
 * and the share of built points near a true wall.
 */
final class MapQuality {

  private MapQuality() {}

  /** Path errors, mm. */
  record PathError(double rms, double max) {}

  /** Places the built frame on the true one: the first scan's laser pose on its true pose. */
  static ArPose toTruth(BuiltMap m, List<ArPose> trueLaser, ArPose mount) {
    ArPose first = Poses.compose(m.trajectory().pose(0), mount);
    return Poses.compose(trueLaser.get(m.trajectory().scanId(0)), Poses.inverse(first));
  }

  static PathError pathError(BuiltMap m, List<ArPose> trueLaser, ArPose mount) {
    ArPose t = toTruth(m, trueLaser, mount);
    Trajectory tr = m.trajectory();
    double sum = 0;
    double max = 0;
    for (int i = 0; i < tr.size(); i++) {
      ArPose est = Poses.compose(t, Poses.compose(tr.pose(i), mount));
      double e = est.findDistanceTo(trueLaser.get(tr.scanId(i)));
      sum += e * e;
      max = Math.max(max, e);
    }
    return new PathError(Math.sqrt(sum / tr.size()), max);
  }

  /**
   * The share (0..1) of built points within {@code tol} mm of a true surface: a line of the true
   * map, or the disc the simulator makes of each of its points (radius half the map's resolution,
   * as the simulator blocks them).
   */
  static double nearWalls(BuiltMap m, ArMap truth, ArPose toTruth, double tol) {
    List<ArLineSegment> lines = truth.getLines();
    ArMapPoints pts = truth.getPoints();
    double disc = truth.getResolution() > 0 ? truth.getResolution() / 2.0 : 10;
    int near = 0;
    for (int i = 0; i < m.pointCount(); i++) {
      ArPose p = Poses.compose(toTruth, new ArPose(m.x(i), m.y(i)));
      double best = Double.MAX_VALUE;
      for (ArLineSegment l : lines) {
        best = Math.min(best, distance(l, p.x(), p.y()));
      }
      for (int k = 0; k < pts.size() && best > tol; k++) {
        double dx = pts.x(k) - p.x();
        double dy = pts.y(k) - p.y();
        best = Math.min(best, Math.max(0, Math.sqrt(dx * dx + dy * dy) - disc));
      }
      if (best <= tol) {
        near++;
      }
    }
    return m.pointCount() == 0 ? 0 : (double) near / m.pointCount();
  }

  /**
   * The share (0..1) of the true walls the laser saw that the built map covers: samples every 50 mm
   * along the true lines, and the true points (discs as in {@link #nearWalls}); a sample with a
   * true laser hit within 50 mm was seen, and is covered if a built point lies within 50 mm.
   */
  static double coverage(BuiltMap m, ArMap truth, ArPose toTruth, List<double[]> trueHits) {
    java.util.Map<Long, List<double[]>> hits = new java.util.HashMap<>();
    for (double[] xy : trueHits) {
      for (int k = 0; k < xy.length; k += 2) {
        bucket(hits, xy[k], xy[k + 1]);
      }
    }
    java.util.Map<Long, List<double[]>> built = new java.util.HashMap<>();
    for (int i = 0; i < m.pointCount(); i++) {
      ArPose p = Poses.compose(toTruth, new ArPose(m.x(i), m.y(i)));
      bucket(built, p.x(), p.y());
    }
    List<double[]> samples = new java.util.ArrayList<>();
    for (ArLineSegment l : truth.getLines()) {
      double len = Math.hypot(l.x2() - l.x1(), l.y2() - l.y1());
      int steps = Math.max(1, (int) Math.round(len / 50));
      for (int k = 0; k <= steps; k++) {
        double t = (double) k / steps;
        samples.add(
            new double[] {l.x1() + t * (l.x2() - l.x1()), l.y1() + t * (l.y2() - l.y1()), 0});
      }
    }
    ArMapPoints pts = truth.getPoints();
    double disc = truth.getResolution() > 0 ? truth.getResolution() / 2.0 : 10;
    for (int k = 0; k < pts.size(); k++) {
      samples.add(new double[] {pts.x(k), pts.y(k), disc});
    }
    int seen = 0;
    int covered = 0;
    for (double[] s : samples) {
      if (within(hits, s[0], s[1], 50 + s[2])) {
        seen++;
        if (within(built, s[0], s[1], 50 + s[2])) {
          covered++;
        }
      }
    }
    return seen == 0 ? 0 : (double) covered / seen;
  }

  private static final double BUCKET = 200;

  private static long key(long cx, long cy) {
    return (cx << 32) ^ (cy & 0xffffffffL);
  }

  private static void bucket(java.util.Map<Long, List<double[]>> grid, double x, double y) {
    long k = key((long) Math.floor(x / BUCKET), (long) Math.floor(y / BUCKET));
    grid.computeIfAbsent(k, c -> new java.util.ArrayList<>()).add(new double[] {x, y});
  }

  private static boolean within(
      java.util.Map<Long, List<double[]>> grid, double x, double y, double r) {
    long cx = (long) Math.floor(x / BUCKET);
    long cy = (long) Math.floor(y / BUCKET);
    for (long dx = -1; dx <= 1; dx++) {
      for (long dy = -1; dy <= 1; dy++) {
        List<double[]> l = grid.get(key(cx + dx, cy + dy));
        if (l == null) {
          continue;
        }
        for (double[] p : l) {
          if (Math.hypot(p[0] - x, p[1] - y) <= r) {
            return true;
          }
        }
      }
    }
    return false;
  }

  static double distance(ArLineSegment l, double x, double y) {
    double dx = l.x2() - l.x1();
    double dy = l.y2() - l.y1();
    double len2 = dx * dx + dy * dy;
    double t = len2 == 0 ? 0 : ((x - l.x1()) * dx + (y - l.y1()) * dy) / len2;
    t = Math.max(0, Math.min(1, t));
    double ex = l.x1() + t * dx - x;
    double ey = l.y1() + t * dy - y;
    return Math.sqrt(ex * ex + ey * ey);
  }
}
