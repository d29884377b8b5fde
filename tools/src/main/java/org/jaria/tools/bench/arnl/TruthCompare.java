package org.jaria.tools.bench.arnl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapPoints;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.Trajectory;

/**
 * A built map and path against the truth: the true map's surfaces (lines, and its points as the
 * simulator's discs of half the map's resolution) in a bucket grid for distance queries.
 */
final class TruthCompare {

  private static final double CELL = 500;

  private final List<ArLineSegment> lines;
  private final ArMapPoints points;
  private final double disc;
  private final Map<Long, List<Integer>> grid = new HashMap<>();

  private TruthCompare(ArMap truth) {
    lines = truth.getLines();
    points = truth.getPoints();
    disc = truth.getResolution() > 0 ? truth.getResolution() / 2.0 : 10;
    for (int i = 0; i < lines.size(); i++) {
      ArLineSegment l = lines.get(i);
      double len = Math.hypot(l.x2() - l.x1(), l.y2() - l.y1());
      int steps = (int) Math.ceil(len / (CELL / 2)) + 1;
      for (int k = 0; k <= steps; k++) {
        double t = (double) k / steps;
        add(l.x1() + t * (l.x2() - l.x1()), l.y1() + t * (l.y2() - l.y1()), i);
      }
    }
    for (int k = 0; k < points.size(); k++) {
      add(points.x(k), points.y(k), -1 - k);
    }
  }

  static TruthCompare of(ArMap truth) {
    return new TruthCompare(truth);
  }

  private static long key(double x, double y) {
    long cx = (long) Math.floor(x / CELL);
    long cy = (long) Math.floor(y / CELL);
    return (cx << 32) ^ (cy & 0xffffffffL);
  }

  private void add(double x, double y, int item) {
    List<Integer> l = grid.computeIfAbsent(key(x, y), k -> new ArrayList<>());
    if (l.isEmpty() || l.get(l.size() - 1).intValue() != item) {
      l.add(item);
    }
  }

  /** Distance from (x, y) to the nearest true surface, up to about a cell (else infinity). */
  double distance(double x, double y) {
    double best = Double.POSITIVE_INFINITY;
    for (int dx = -1; dx <= 1; dx++) {
      for (int dy = -1; dy <= 1; dy++) {
        List<Integer> l = grid.get(key(x + dx * CELL, y + dy * CELL));
        if (l == null) {
          continue;
        }
        for (int item : l) {
          double d;
          if (item >= 0) {
            d = segment(lines.get(item), x, y);
          } else {
            int k = -1 - item;
            d = Math.max(0, Math.hypot(points.x(k) - x, points.y(k) - y) - disc);
          }
          best = Math.min(best, d);
        }
      }
    }
    return best;
  }

  private static double segment(ArLineSegment l, double x, double y) {
    double dx = l.x2() - l.x1();
    double dy = l.y2() - l.y1();
    double len2 = dx * dx + dy * dy;
    double t = len2 == 0 ? 0 : ((x - l.x1()) * dx + (y - l.y1()) * dy) / len2;
    t = Math.max(0, Math.min(1, t));
    return Math.hypot(l.x1() + t * dx - x, l.y1() + t * dy - y);
  }

  /** Places the built frame on the true one by the first scan's laser pose. */
  static ArPose toTruth(BuiltMap m, List<ArPose> trueLaser, ArPose mount) {
    Trajectory t = m.trajectory();
    ArPose first = compose(t.pose(0), mount);
    return compose(trueLaser.get(t.scanId(0)), inverse(first));
  }

  /** RMS and max error of the corrected laser poses, mm. */
  static double[] pathError(Trajectory t, List<ArPose> trueLaser, ArPose toTruth, ArPose mount) {
    double sum = 0;
    double max = 0;
    for (int i = 0; i < t.size(); i++) {
      ArPose est = compose(toTruth, compose(t.pose(i), mount));
      double e = est.findDistanceTo(trueLaser.get(t.scanId(i)));
      sum += e * e;
      max = Math.max(max, e);
    }
    return new double[] {Math.sqrt(sum / t.size()), max};
  }

  /** Shares of the built points within 50 mm of a true surface, and 50 to 300 mm off one. */
  double[] nearShares(BuiltMap m, ArPose toTruth) {
    int near = 0;
    int off = 0;
    for (int i = 0; i < m.pointCount(); i++) {
      ArPose p = compose(toTruth, new ArPose(m.x(i), m.y(i)));
      double d = distance(p.x(), p.y());
      if (d <= 50) {
        near++;
      } else if (d <= 300) {
        off++;
      }
    }
    double n = Math.max(1, m.pointCount());
    return new double[] {near / n, off / n};
  }

  /**
   * Of the true walls the laser saw (samples every 50 mm along the true lines, and the true points,
   * with a true laser hit within 50 mm), the share with a built point within 50 mm.
   */
  double coverage(BuiltMap m, ArPose toTruth, List<double[]> trueHits) {
    Map<Long, List<double[]>> hits = new HashMap<>();
    for (double[] xy : trueHits) {
      for (int k = 0; k < xy.length; k += 2) {
        hits.computeIfAbsent(key(xy[k], xy[k + 1]), c -> new ArrayList<>())
            .add(new double[] {xy[k], xy[k + 1]});
      }
    }
    Map<Long, List<double[]>> built = new HashMap<>();
    for (int i = 0; i < m.pointCount(); i++) {
      ArPose p = compose(toTruth, new ArPose(m.x(i), m.y(i)));
      built
          .computeIfAbsent(key(p.x(), p.y()), c -> new ArrayList<>())
          .add(new double[] {p.x(), p.y()});
    }
    int seen = 0;
    int covered = 0;
    List<double[]> samples = new ArrayList<>();
    for (ArLineSegment l : lines) {
      double len = Math.hypot(l.x2() - l.x1(), l.y2() - l.y1());
      int steps = Math.max(1, (int) Math.round(len / 50));
      for (int k = 0; k <= steps; k++) {
        double t = (double) k / steps;
        samples.add(
            new double[] {l.x1() + t * (l.x2() - l.x1()), l.y1() + t * (l.y2() - l.y1()), 0});
      }
    }
    for (int k = 0; k < points.size(); k++) {
      samples.add(new double[] {points.x(k), points.y(k), disc});
    }
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

  private static boolean within(Map<Long, List<double[]>> g, double x, double y, double r) {
    for (int dx = -1; dx <= 1; dx++) {
      for (int dy = -1; dy <= 1; dy++) {
        List<double[]> l = g.get(key(x + dx * CELL, y + dy * CELL));
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

  static ArPose compose(ArPose a, ArPose b) {
    double c = Math.cos(a.getThRad());
    double s = Math.sin(a.getThRad());
    return new ArPose(
        a.x() + c * b.x() - s * b.y(), a.y() + s * b.x() + c * b.y(), a.th() + b.th());
  }

  static ArPose inverse(ArPose a) {
    double c = Math.cos(a.getThRad());
    double s = Math.sin(a.getThRad());
    return new ArPose(-c * a.x() - s * a.y(), s * a.x() - c * a.y(), -a.th());
  }
}
