package org.jaria.mapping;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jaria.geom.ArLineSegment;

/**
 * Fits the map's LINES to the walls: each scan's points (in sweep order, placed by its corrected
 * pose) are cut where they jump, then split where they bend (split-and-merge) into straight runs;
 * runs of all scans that lie on one wall are merged into one line (a least-squares fit through all
 * their points, spanning all of them). What SonARNL's sonar model and the editor see as walls.
 */
final class LineFitter {

  /** A run bends when a point lies farther than this from the line through its ends, mm. */
  static final double SPLIT_MM = 30;

  /** Runs on one wall: headings within this, degrees. */
  static final double MERGE_DEG = 3;

  /** ... each end within this of the other's line, mm. */
  static final double MERGE_OFFSET_MM = 50;

  /** ... and no wider gap between them than this, mm. */
  static final double MERGE_GAP_MM = 250;

  /** Lines shorter than this are left out of the map, mm. */
  static final double MIN_LENGTH_MM = 500;

  private static final int MIN_POINTS = 6;

  /** A straight run: its points' moments and its extent along its line. */
  private static final class Run {
    double n;
    double sx;
    double sy;
    double sxx;
    double sxy;
    double syy;
    // the line: a point on it, the unit direction, and the extent as positions along it
    double cx;
    double cy;
    double dx;
    double dy;
    double lo;
    double hi;
    boolean dead;

    void fit() {
      cx = sx / n;
      cy = sy / n;
      double xx = sxx / n - cx * cx;
      double xy = sxy / n - cx * cy;
      double yy = syy / n - cy * cy;
      double a = 0.5 * Math.atan2(2 * xy, xx - yy);
      dx = Math.cos(a);
      dy = Math.sin(a);
    }

    double along(double x, double y) {
      return (x - cx) * dx + (y - cy) * dy;
    }

    double off(double x, double y) {
      return Math.abs(-(x - cx) * dy + (y - cy) * dx);
    }

    double x(double t) {
      return cx + t * dx;
    }

    double y(double t) {
      return cy + t * dy;
    }

    double angle() {
      double a = Math.toDegrees(Math.atan2(dy, dx));
      return a < 0 ? a + 180 : a >= 180 ? a - 180 : a;
    }
  }

  private final List<Run> runs = new ArrayList<>();

  /** Adds one scan's points (map frame, sweep order); {@code ox, oy} is where the laser was. */
  void addScan(double[] x, double[] y, int n, double ox, double oy) {
    int start = 0;
    for (int i = 1; i <= n; i++) {
      boolean cut = i == n;
      if (!cut) {
        double gx = x[i] - x[i - 1];
        double gy = y[i] - y[i - 1];
        double gap = Math.sqrt(gx * gx + gy * gy);
        double rx = x[i] - ox;
        double ry = y[i] - oy;
        double range = Math.sqrt(rx * rx + ry * ry);
        cut = gap > Math.max(150, 0.035 * range);
      }
      if (cut) {
        split(x, y, start, i - 1);
        start = i;
      }
    }
  }

  private void split(double[] x, double[] y, int a, int b) {
    if (b - a + 1 < MIN_POINTS) {
      return;
    }
    double lx = x[b] - x[a];
    double ly = y[b] - y[a];
    double len = Math.hypot(lx, ly);
    if (len < 1e-9) {
      return;
    }
    int worst = -1;
    double worstD = SPLIT_MM;
    for (int i = a + 1; i < b; i++) {
      double d = Math.abs((x[i] - x[a]) * ly - (y[i] - y[a]) * lx) / len;
      if (d > worstD) {
        worstD = d;
        worst = i;
      }
    }
    if (worst >= 0) {
      split(x, y, a, worst);
      split(x, y, worst, b);
      return;
    }
    if (len < MIN_LENGTH_MM / 2) {
      return;
    }
    Run r = new Run();
    for (int i = a; i <= b; i++) {
      r.n++;
      r.sx += x[i];
      r.sy += y[i];
      r.sxx += x[i] * x[i];
      r.sxy += x[i] * y[i];
      r.syy += y[i] * y[i];
    }
    r.fit();
    r.lo = Math.min(r.along(x[a], y[a]), r.along(x[b], y[b]));
    r.hi = Math.max(r.along(x[a], y[a]), r.along(x[b], y[b]));
    runs.add(r);
  }

  /** Merges the runs of all scans and returns the walls' lines. */
  List<ArLineSegment> lines() {
    boolean changed = true;
    for (int pass = 0; changed && pass < 20; pass++) {
      changed = mergePass();
    }
    List<ArLineSegment> out = new ArrayList<>();
    for (Run r : runs) {
      if (!r.dead && r.hi - r.lo >= MIN_LENGTH_MM && r.n >= 2 * MIN_POINTS) {
        out.add(
            new ArLineSegment(
                Math.rint(r.x(r.lo)),
                Math.rint(r.y(r.lo)),
                Math.rint(r.x(r.hi)),
                Math.rint(r.y(r.hi))));
      }
    }
    out.sort(
        Comparator.comparingDouble(ArLineSegment::x1)
            .thenComparingDouble(ArLineSegment::y1)
            .thenComparingDouble(ArLineSegment::x2)
            .thenComparingDouble(ArLineSegment::y2));
    return out;
  }

  /** One pass over angle buckets: merges runs on the same wall; whether any merged. */
  private boolean mergePass() {
    Map<Integer, List<Run>> buckets = new HashMap<>();
    for (Run r : runs) {
      if (!r.dead) {
        buckets.computeIfAbsent((int) (r.angle() / MERGE_DEG), k -> new ArrayList<>()).add(r);
      }
    }
    int nb = (int) Math.ceil(180 / MERGE_DEG);
    boolean changed = false;
    for (Map.Entry<Integer, List<Run>> e : buckets.entrySet()) {
      List<Run> near = new ArrayList<>(e.getValue());
      List<Run> next = buckets.get((e.getKey() + 1) % nb);
      if (next != null) {
        near.addAll(next);
      }
      near.sort(Comparator.comparingDouble((Run r) -> -r.n));
      for (int i = 0; i < near.size(); i++) {
        Run a = near.get(i);
        for (int j = i + 1; j < near.size() && !a.dead; j++) {
          Run b = near.get(j);
          if (!b.dead && a != b && mergeable(a, b)) {
            absorb(a, b);
            changed = true;
          }
        }
      }
    }
    runs.removeIf(r -> r.dead);
    return changed;
  }

  private static boolean mergeable(Run a, Run b) {
    double da = Math.abs(a.angle() - b.angle());
    if (Math.min(da, 180 - da) > MERGE_DEG) {
      return false;
    }
    double bx0 = b.x(b.lo);
    double by0 = b.y(b.lo);
    double bx1 = b.x(b.hi);
    double by1 = b.y(b.hi);
    if (a.off(bx0, by0) > MERGE_OFFSET_MM || a.off(bx1, by1) > MERGE_OFFSET_MM) {
      return false;
    }
    double t0 = a.along(bx0, by0);
    double t1 = a.along(bx1, by1);
    double lo = Math.min(t0, t1);
    double hi = Math.max(t0, t1);
    return lo <= a.hi + MERGE_GAP_MM && hi >= a.lo - MERGE_GAP_MM;
  }

  private static void absorb(Run a, Run b) {
    double[] ends = {
      b.x(b.lo), b.y(b.lo), b.x(b.hi), b.y(b.hi), a.x(a.lo), a.y(a.lo), a.x(a.hi), a.y(a.hi)
    };
    a.n += b.n;
    a.sx += b.sx;
    a.sy += b.sy;
    a.sxx += b.sxx;
    a.sxy += b.sxy;
    a.syy += b.syy;
    a.fit();
    a.lo = Double.POSITIVE_INFINITY;
    a.hi = Double.NEGATIVE_INFINITY;
    for (int k = 0; k < ends.length; k += 2) {
      double t = a.along(ends[k], ends[k + 1]);
      a.lo = Math.min(a.lo, t);
      a.hi = Math.max(a.hi, t);
    }
    b.dead = true;
  }
}
