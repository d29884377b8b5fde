package org.jaria.mapping;

import java.util.Arrays;
import org.jaria.geom.ArMath;

/**
 * Finds where a scan fits into a reference when the guess may be off: every pose on a grid of
 * positions and headings around the guess is scored by how many scan points fall on or next to a
 * reference point, first coarsely, then finely around the best few. Unlike ICP, which follows the
 * nearest points downhill and can settle in the wrong place where the view is poor (a doorway seen
 * while turning), this compares whole fits; ICP then polishes the winner. The loop closer searches
 * metres and tens of degrees (100 mm, 2 degrees, then 40 mm, 0.5 degrees); each scan's own match
 * searches a few centimetres (50 mm, 1 degree, then 20 mm, 0.5 degrees).
 *
 * <p>Scores are read from rasters of the reference (a cell holding a point scores 2, its neighbours
 * 1) of primitive arrays, reused between searches. Not thread-safe.
 */
final class CorrelativeSearch {

  private static final int KEEP = 3;
  private final Raster coarse;
  private final Raster fine;
  private final double coarseStep;
  private final double coarseAngle;
  private final double fineStep;
  private final double fineAngle;
  private double[] rx = new double[512];
  private double[] ry = new double[512];

  // result
  double x;
  double y;
  double thDeg;
  double score;

  /** A search on a coarse and a fine raster, each stepped by its cell size. */
  CorrelativeSearch(double coarseCell, double coarseAngle, double fineCell, double fineAngle) {
    this.coarse = new Raster(coarseCell);
    this.fine = new Raster(fineCell);
    this.coarseStep = coarseCell;
    this.coarseAngle = coarseAngle;
    this.fineStep = fineCell;
    this.fineAngle = fineAngle;
  }

  /** The loop closer's search: metres and tens of degrees. */
  static CorrelativeSearch wide() {
    return new CorrelativeSearch(100, 2, 40, 0.5);
  }

  /** A scan's own match: centimetres and degrees. */
  static CorrelativeSearch narrow() {
    return new CorrelativeSearch(50, 1, 20, 0.5);
  }

  /**
   * Searches within {@code radius} mm and {@code angleWindow} degrees of (x0, y0, th0); the best
   * pose and its score (the fraction of the best possible) are in the fields.
   */
  void search(
      PointIndex ref,
      double[] sx,
      double[] sy,
      int n,
      double x0,
      double y0,
      double th0,
      double radius,
      double angleWindow) {
    this.radius = Math.max(1, radius);
    this.window = angleWindow;
    // the rasters need to cover only where the scan can land
    double cos = Math.cos(Math.toRadians(th0));
    double sin = Math.sin(Math.toRadians(th0));
    double reach = 0;
    double bx0 = Double.POSITIVE_INFINITY;
    double by0 = Double.POSITIVE_INFINITY;
    double bx1 = Double.NEGATIVE_INFINITY;
    double by1 = Double.NEGATIVE_INFINITY;
    for (int i = 0; i < n; i++) {
      double px = x0 + cos * sx[i] - sin * sy[i];
      double py = y0 + sin * sx[i] + cos * sy[i];
      bx0 = Math.min(bx0, px);
      by0 = Math.min(by0, py);
      bx1 = Math.max(bx1, px);
      by1 = Math.max(by1, py);
      reach = Math.max(reach, sx[i] * sx[i] + sy[i] * sy[i]);
    }
    double grow =
        radius + Math.sqrt(reach) * Math.toRadians(angleWindow + coarseAngle) + 2 * coarseStep;
    coarse.build(ref, bx0 - grow, by0 - grow, bx1 + grow, by1 + grow);
    fine.build(ref, bx0 - grow, by0 - grow, bx1 + grow, by1 + grow);
    if (rx.length < n) {
      rx = new double[n];
      ry = new double[n];
    }
    double[] bestScore = new double[KEEP];
    double[] bestX = new double[KEEP];
    double[] bestY = new double[KEEP];
    double[] bestT = new double[KEEP];
    Arrays.fill(bestScore, -1);
    for (double dt = -angleWindow; dt <= angleWindow + 1e-9; dt += coarseAngle) {
      rotate(sx, sy, n, th0 + dt);
      for (double dx = -radius; dx <= radius + 1e-9; dx += coarseStep) {
        for (double dy = -radius; dy <= radius + 1e-9; dy += coarseStep) {
          double s = coarse.score(rx, ry, n, x0 + dx, y0 + dy) - penalty(n, dx, dy, dt);
          insert(bestScore, bestX, bestY, bestT, s, x0 + dx, y0 + dy, th0 + dt);
        }
      }
    }
    score = -1;
    for (int k = 0; k < KEEP; k++) {
      if (bestScore[k] < 0) {
        continue;
      }
      for (double dt = -coarseAngle; dt <= coarseAngle + 1e-9; dt += fineAngle) {
        rotate(sx, sy, n, bestT[k] + dt);
        for (double dx = -coarseStep; dx <= coarseStep + 1e-9; dx += fineStep) {
          for (double dy = -coarseStep; dy <= coarseStep + 1e-9; dy += fineStep) {
            double s =
                fine.score(rx, ry, n, bestX[k] + dx, bestY[k] + dy)
                    - penalty(
                        n,
                        bestX[k] + dx - x0,
                        bestY[k] + dy - y0,
                        ArMath.subAngle(bestT[k] + dt, th0));
            if (s > score) {
              score = s;
              x = bestX[k] + dx;
              y = bestY[k] + dy;
              thDeg = bestT[k] + dt;
            }
          }
        }
      }
    }
    score = n == 0 ? 0 : score / (2.0 * n);
  }

  /**
   * A small cost for straying from the guess: of several equally good fits (along a featureless
   * corridor) the one nearest the guess wins; a clearly better fit farther away still does.
   */
  private double penalty(int n, double dx, double dy, double dt) {
    double r = (dx * dx + dy * dy) / (radius * radius);
    double a = window > 0 ? (dt * dt) / (window * window) : 0;
    return PENALTY * n * (r + a);
  }

  /** Points' worth of score lost at the edge of the search window, per point of the scan. */
  private static final double PENALTY = 0.1;

  private double radius = 1;
  private double window = 1;

  private void rotate(double[] sx, double[] sy, int n, double thDeg) {
    double c = Math.cos(Math.toRadians(thDeg));
    double s = Math.sin(Math.toRadians(thDeg));
    for (int i = 0; i < n; i++) {
      rx[i] = c * sx[i] - s * sy[i];
      ry[i] = s * sx[i] + c * sy[i];
    }
  }

  private static void insert(
      double[] bs, double[] bx, double[] by, double[] bt, double s, double x, double y, double t) {
    int at = -1;
    for (int k = 0; k < bs.length; k++) {
      if (s > bs[k]) {
        at = k;
        break;
      }
    }
    if (at < 0) {
      return;
    }
    for (int k = bs.length - 1; k > at; k--) {
      bs[k] = bs[k - 1];
      bx[k] = bx[k - 1];
      by[k] = by[k - 1];
      bt[k] = bt[k - 1];
    }
    bs[at] = s;
    bx[at] = x;
    by[at] = y;
    bt[at] = t;
  }

  /** A byte raster of the reference: 2 on a point's cell, 1 next to it. */
  private static final class Raster {
    private final double cell;
    private byte[] v = new byte[0];
    private double minX;
    private double minY;
    private int w;
    private int h;

    Raster(double cell) {
      this.cell = cell;
    }

    /** Rasterises the reference points within the box (x0, y0)..(x1, y1). */
    void build(PointIndex ref, double x0, double y0, double x1, double y1) {
      if (!(x1 >= x0 && y1 >= y0)) {
        w = 0;
        h = 0;
        return;
      }
      minX = x0 - cell;
      minY = y0 - cell;
      w = (int) ((x1 - minX) / cell) + 2;
      h = (int) ((y1 - minY) / cell) + 2;
      if (v.length < w * h) {
        v = new byte[w * h];
      } else {
        Arrays.fill(v, 0, w * h, (byte) 0);
      }
      for (int i = 0; i < ref.size(); i++) {
        int gx = (int) ((ref.x(i) - minX) / cell);
        int gy = (int) ((ref.y(i) - minY) / cell);
        if (gx < 1 || gy < 1 || gx >= w - 1 || gy >= h - 1) {
          continue;
        }
        for (int yy = gy - 1; yy <= gy + 1; yy++) {
          for (int xx = gx - 1; xx <= gx + 1; xx++) {
            int k = yy * w + xx;
            if (v[k] == 0) {
              v[k] = 1;
            }
          }
        }
        v[gy * w + gx] = 2;
      }
    }

    int score(double[] rx, double[] ry, int n, double tx, double ty) {
      int s = 0;
      for (int i = 0; i < n; i++) {
        int gx = (int) ((rx[i] + tx - minX) / cell);
        int gy = (int) ((ry[i] + ty - minY) / cell);
        if (gx >= 0 && gy >= 0 && gx < w && gy < h) {
          s += v[gy * w + gx];
        }
      }
      return s;
    }
  }
}
