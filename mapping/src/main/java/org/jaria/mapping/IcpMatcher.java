package org.jaria.mapping;

/**
 * Point-to-line ICP: moves a scan, starting at a guessed pose, until its points lie on the
 * reference's surfaces. Each round pairs every scan point with the nearest reference point (within
 * a distance that shrinks from round to round), measures how far the scan point lies off that
 * point's surface (along its normal), and takes the Gauss-Newton step that shrinks those distances,
 * with large ones weighted down (Huber) so that a pillar or a person does not pull the scan. A weak
 * pull towards the guess keeps a match along a featureless corridor where the guess (odometry) put
 * it.
 *
 * <p>The work is on primitive arrays; a match allocates nothing. Not thread-safe: one per builder.
 */
final class IcpMatcher {

  /** Residuals up to this are weighted fully, larger ones less (Huber), mm. */
  static final double HUBER_MM = 20;

  /** A scan point within this of a reference point overlaps the reference, mm. */
  static final double OVERLAP_MM = 250;

  /** Standard deviation assumed for one point's distance, mm (for the information matrix). */
  static final double POINT_SIGMA_MM = 15;

  /**
   * A scan's points err together (a slightly wrong heading, a wall's texture), so however many pair
   * up, they are trusted as much as this many independent points.
   */
  static final double WORTH_POINTS = 20;

  private static final double[] SCHEDULE = {250, 180, 120, 90, 70, 60, 50};
  private static final int MAX_ROUNDS = 30;
  private double priorMm = 600;
  private double priorRad = Math.toRadians(20);

  /**
   * How far the guess may be off (standard deviations, mm and degrees): the pull towards the guess
   * that keeps a match where odometry put it along a featureless corridor.
   */
  void setPrior(double sigmaMm, double sigmaDeg) {
    priorMm = sigmaMm;
    priorRad = Math.toRadians(sigmaDeg);
  }

  // the result of the last match
  double x;
  double y;
  double thDeg;
  double inlierFraction;

  /**
   * The share of the scan points near the reference (within {@link #OVERLAP_MM}) that lie on it:
   * how well the scan fits where it overlaps the reference, whatever else it sees.
   */
  double overlapInliers;

  /** Scan points with a reference point within {@link #OVERLAP_MM} at the result. */
  int partnered;

  int pairs;
  int rounds;

  /** Information of the last result, units mm and rad: xx, xy, xt, yy, yt, tt. */
  final double[] info = new double[6];

  private final double[] h = new double[6];
  private final double[] g = new double[3];
  private final double[] step = new double[3];
  private int[] partner = new int[256];
  private double[] err = new double[256];
  private double[] sorted = new double[256];

  /** The share of pairs kept each round (the closest ones). */
  static final double TRIM = 0.8;

  /**
   * Matches {@code count} scan points ({@code sx, sy}, robot frame) against {@code ref}, starting
   * at (x0, y0, th0Deg); the result is in this object's fields.
   */
  void match(
      PointIndex ref, double[] sx, double[] sy, int count, double x0, double y0, double th0Deg) {
    double tx = x0;
    double ty = y0;
    double tt = Math.toRadians(th0Deg);
    double t0 = tt;
    int round = 0;
    for (; round < MAX_ROUNDS; round++) {
      double maxDist = SCHEDULE[Math.min(round, SCHEDULE.length - 1)];
      accumulate(ref, sx, sy, count, tx, ty, tt, maxDist, false);
      // the pull towards the guess, in the units of the points' squared distances: one point's
      // distance has a standard deviation of POINT_SIGMA_MM, and the points of a scan are
      // trusted no more than WORTH_POINTS independent ones (as the information below is)
      double k = POINT_SIGMA_MM * POINT_SIGMA_MM * Math.max(1, pairs / WORTH_POINTS);
      double px = k / (priorMm * priorMm);
      double pt = k / (priorRad * priorRad);
      h[0] += px;
      h[3] += px;
      h[5] += pt;
      g[0] += px * (tx - x0);
      g[1] += px * (ty - y0);
      g[2] += pt * (tt - t0);
      if (!solve3(h, g, step)) {
        break;
      }
      tx -= step[0];
      ty -= step[1];
      tt -= step[2];
      boolean small = Math.abs(step[0]) < 0.05 && Math.abs(step[1]) < 0.05;
      if (small && Math.abs(step[2]) < 1e-5 && round >= SCHEDULE.length - 1) {
        round++;
        break;
      }
    }
    rounds = round;
    x = tx;
    y = ty;
    thDeg = Math.toDegrees(tt);
    int inliers = accumulate(ref, sx, sy, count, tx, ty, tt, OVERLAP_MM, true);
    inlierFraction = count == 0 ? 0 : (double) inliers / count;
    overlapInliers = partnered == 0 ? 0 : (double) inliers / partnered;
    double scale = 1 / (POINT_SIGMA_MM * POINT_SIGMA_MM * Math.max(1, pairs / WORTH_POINTS));
    for (int k = 0; k < 6; k++) {
      info[k] = h[k] * scale;
    }
  }

  /**
   * Fills h (upper triangle of J'WJ) and g (J'Wr) for the pose; returns the pairs within {@code
   * maxDist} (also in {@link #pairs}). With {@code inliersOnly}: unweighted, and only pairs within
   * 1.5 Huber widths of their surface (the inliers), for the information and the fit's quality.
   */
  private int accumulate(
      PointIndex ref,
      double[] sx,
      double[] sy,
      int count,
      double tx,
      double ty,
      double tt,
      double maxDist,
      boolean inliersOnly) {
    java.util.Arrays.fill(h, 0);
    java.util.Arrays.fill(g, 0);
    if (partner.length < count) {
      partner = new int[count];
      err = new double[count];
      sorted = new double[count];
    }
    double c = Math.cos(tt);
    double s = Math.sin(tt);
    // pass 1: partners and their distances (to the surface, or to the point)
    int paired = 0;
    for (int k = 0; k < count; k++) {
      double px = c * sx[k] - s * sy[k] + tx;
      double py = s * sx[k] + c * sy[k] + ty;
      int q = ref.nearest(px, py, maxDist);
      if (q >= 0 && Double.isNaN(ref.ny(q))) {
        q = -1; // a lone reference point: nothing to match against
      }
      partner[k] = q;
      if (q < 0) {
        continue;
      }
      double ex = px - ref.x(q);
      double ey = py - ref.y(q);
      double nx = ref.nx(q);
      err[k] = Double.isNaN(nx) ? Math.sqrt(ex * ex + ey * ey) : Math.abs(nx * ex + ref.ny(q) * ey);
      sorted[paired++] = err[k];
    }
    partnered = paired;
    // the worst fifth of the pairs are most likely points the reference never saw: left out
    double limit = HUBER_MM * 1.5;
    if (!inliersOnly && paired > 10) {
      java.util.Arrays.sort(sorted, 0, paired);
      limit = Math.max(HUBER_MM, sorted[(int) (paired * TRIM)]);
    }
    int n = 0;
    for (int k = 0; k < count; k++) {
      int q = partner[k];
      if (q < 0 || err[k] > limit) {
        continue;
      }
      double lx = sx[k];
      double ly = sy[k];
      double px = c * lx - s * ly + tx;
      double py = s * lx + c * ly + ty;
      double ex = px - ref.x(q);
      double ey = py - ref.y(q);
      double dxt = -s * lx - c * ly;
      double dyt = c * lx - s * ly;
      double nx = ref.nx(q);
      double ny = ref.ny(q);
      double ar = err[k];
      double w = inliersOnly || ar <= HUBER_MM ? 1 : HUBER_MM / ar;
      if (Double.isNaN(nx)) {
        // no surface here (a corner, a post): point to point, both coordinates
        h[0] += w;
        h[2] += w * dxt;
        h[3] += w;
        h[4] += w * dyt;
        h[5] += w * (dxt * dxt + dyt * dyt);
        g[0] += w * ex;
        g[1] += w * ey;
        g[2] += w * (dxt * ex + dyt * ey);
      } else {
        double r = nx * ex + ny * ey;
        double jt = nx * dxt + ny * dyt;
        h[0] += w * nx * nx;
        h[1] += w * nx * ny;
        h[2] += w * nx * jt;
        h[3] += w * ny * ny;
        h[4] += w * ny * jt;
        h[5] += w * jt * jt;
        g[0] += w * nx * r;
        g[1] += w * ny * r;
        g[2] += w * jt * r;
      }
      n++;
    }
    pairs = n;
    return n;
  }

  /** Solves the symmetric 3x3 system (upper triangle a) a x = b; false if singular. */
  static boolean solve3(double[] a, double[] b, double[] out) {
    double a00 = a[0];
    double a01 = a[1];
    double a02 = a[2];
    double a11 = a[3];
    double a12 = a[4];
    double a22 = a[5];
    double c00 = a11 * a22 - a12 * a12;
    double c01 = a02 * a12 - a01 * a22;
    double c02 = a01 * a12 - a02 * a11;
    double det = a00 * c00 + a01 * c01 + a02 * c02;
    if (!(Math.abs(det) > 1e-300) || !Double.isFinite(det)) {
      return false;
    }
    double c11 = a00 * a22 - a02 * a02;
    double c12 = a01 * a02 - a00 * a12;
    double c22 = a00 * a11 - a01 * a01;
    out[0] = (c00 * b[0] + c01 * b[1] + c02 * b[2]) / det;
    out[1] = (c01 * b[0] + c11 * b[1] + c12 * b[2]) / det;
    out[2] = (c02 * b[0] + c12 * b[1] + c22 * b[2]) / det;
    return Double.isFinite(out[0]) && Double.isFinite(out[1]) && Double.isFinite(out[2]);
  }
}
