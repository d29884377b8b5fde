package org.jaria.mapping;

import org.jaria.geom.ArPose;

/**
 * Recognises a place seen long before: when the robot comes within the search radius of a pose it
 * left at least {@code loopMinTravelMm} of driving ago, its scan is matched against the points of
 * the old poses around there. If the scan fits well, an edge "this pose, seen from that old one"
 * joins the graph, and when it disagrees with the current estimates the graph is optimised, which
 * straightens the whole loop. A fit is tried from the current estimate first (cheap, and enough
 * once the loop has been closed); otherwise by a correlative search over the radius.
 *
 * <p>The search radius grows with the driving since the last closure, as odometry and matching
 * errors do. Not thread-safe.
 */
final class LoopCloser {

  /**
   * A scan fits a place when this share of its points near the place's points lies on the place's
   * surfaces (what the scan sees beyond the place, seen from elsewhere, does not count against it).
   */
  static final double MIN_INLIERS = 0.75;

  /** ... and at least this share of all its points. */
  static final double MIN_SHARE = 0.3;

  /** Fewer matched points than this prove nothing. */
  static final int MIN_PAIRS = 30;

  /** The old poses within this of the candidate make up the place's points, mm. */
  private static final double PLACE_RADIUS_MM = 6000;

  /**
   * A closure that moves the estimate more than this (mm, or degrees) triggers optimisation. The
   * office's laps are sensitive to it (its corridor is featureless along its length, and when the
   * graph is optimised changes what later scans are matched against): in the benchmark's 3 laps and
   * the test's 2, path RMS / max error was 31 / 74 and 27 / 88 mm at 25, 35 / 89 and 25 / 91 at 30,
   * 18 / 43 and 28 / 75 at 35, 17 / 83 and 30 / 90 at 40, 20 / 51 and 35 / 93 at 50.
   */
  private static final double OPTIMIZE_MM = 35;

  private static final double OPTIMIZE_DEG = 0.4;

  private static final double MAX_RADIUS_MM = 5000;

  private final MapBuilderParams params;
  private final PointIndex place = new PointIndex();
  private final IcpMatcher icp = new IcpMatcher();
  private final CorrelativeSearch search = CorrelativeSearch.wide();
  private double travelAtLastClosure;
  private int lastTry = -10;
  private int closures;
  private int optimizations;
  private int rejected;
  private int dropped;
  private int tries;
  private long optimizeNanos;

  LoopCloser(MapBuilderParams params) {
    this.params = params;
  }

  int closures() {
    return closures;
  }

  /** Attempts (a candidate place found and matched against), and time spent optimising. */
  String timing() {
    return String.format(
        java.util.Locale.ROOT,
        "%d loop attempts, %d optimisations %.0f ms",
        tries,
        optimizations,
        optimizeNanos / 1e6);
  }

  int optimizations() {
    return optimizations;
  }

  int rejected() {
    return rejected;
  }

  /** Loop edges dropped because they disagreed with the rest of the graph. */
  int dropped() {
    return dropped;
  }

  /**
   * Tries to close a loop at the newest node {@code i}, whose scan points are {@code p}.
   *
   * @return whether an edge was added
   */
  boolean tryClose(Nodes nodes, int i, ScanPoints p) {
    if (i - lastTry < 2 || p.matchCount < MIN_PAIRS) {
      return false;
    }
    double driven = nodes.travel(i) - travelAtLastClosure;
    double radius =
        Math.min(
            MAX_RADIUS_MM, params.loopSearchMm() + params.loopSearchPerMetre() * driven / 1000);
    int best = -1;
    double bestD = radius * radius;
    double oldest = nodes.travel(i) - params.loopMinTravelMm();
    for (int j = 0; j < i; j++) {
      if (nodes.travel(j) > oldest) {
        break;
      }
      double d = nodes.distanceSq(i, j);
      if (d < bestD && nodes.points(j) != null) {
        bestD = d;
        best = j;
      }
    }
    if (best < 0) {
      return false;
    }
    lastTry = i;
    tries++;
    place.clear();
    double r2 = PLACE_RADIUS_MM * PLACE_RADIUS_MM;
    for (int k = 0; k < i && nodes.travel(k) <= oldest; k++) {
      if (nodes.distanceSq(k, best) <= r2) {
        nodes.addPoints(k, place);
      }
    }
    place.build();
    ArPose est = nodes.estimate(i);
    icp.setPrior(radius, 10);
    icp.match(place, p.kx, p.ky, p.matchCount, est.x(), est.y(), est.th());
    boolean ok = fits(est, radius);
    if (!ok) {
      double window = Math.min(20, 4 + 0.25 * driven / 1000);
      search.search(place, p.kx, p.ky, p.matchCount, est.x(), est.y(), est.th(), radius, window);
      icp.match(place, p.kx, p.ky, p.matchCount, search.x, search.y, search.thDeg);
      ok = fits(est, radius + 200);
    }
    if (!ok) {
      rejected++;
      return false;
    }
    ArPose matched = new ArPose(icp.x, icp.y, icp.thDeg);
    ArPose rel = Poses.between(nodes.estimate(best), matched);
    nodes.graph.addEdge(
        best, i, rel.x(), rel.y(), rel.th(), MapBuilder.toGraphInfo(icp.info, matched.th()), true);
    closures++;
    travelAtLastClosure = nodes.travel(i);
    if (matched.findDistanceTo(est) > OPTIMIZE_MM
        || Math.abs(org.jaria.geom.ArMath.subAngle(matched.th(), est.th())) > OPTIMIZE_DEG) {
      optimize(nodes);
    }
    return true;
  }

  private boolean fits(ArPose est, double radius) {
    return icp.overlapInliers >= MIN_INLIERS
        && icp.inlierFraction >= MIN_SHARE
        && icp.pairs >= MIN_PAIRS
        && Math.hypot(icp.x - est.x(), icp.y - est.y()) <= radius;
  }

  /** Optimises the graph, dropping loop edges that disagree with everything else. */
  void optimize(Nodes nodes) {
    optimizations++;
    long t0 = System.nanoTime();
    dropped += nodes.graph.optimizeDroppingOutliers(15, MAX_LOOP_CHI2);
    optimizeNanos += System.nanoTime() - t0;
  }

  /**
   * A loop edge whose weighted squared error stays above this after optimising is a false match
   * (the chi-square 99.99 % point for 3 degrees of freedom is about 21).
   */
  static final double MAX_LOOP_CHI2 = 50;
}
