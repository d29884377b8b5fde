package org.jaria.arnl.mcl;

import org.jaria.geom.ArPose;

/** The localization score: how many of a scan's echoes the map explains from a pose. */
final class MatchScore {

  private MatchScore() {}

  /**
   * Share of the scan's echoes that the map explains from {@code pose} (ARNL's localization score):
   * an echo is explained when the nearest mapped surface in its cone (found by tracing the cone's
   * rays through the distance field) lies within {@code matchDistance} of its range. This is
   * stricter than the filter's own arc test, so that a robot carried elsewhere scores low even
   * where some arc happens to touch a wall. −1 if the scan has no echoes.
   */
  static double matchFraction(
      LikelihoodField field, ArPose pose, SonarScan scan, double matchDistance) {
    int m = scan.size();
    if (m == 0) {
      return -1;
    }
    double r = Math.toRadians(pose.th());
    double c = Math.cos(r);
    double s = Math.sin(r);
    int k = scan.arcSamples();
    int matched = 0;
    for (int e = 0; e < m; e++) {
      double range = scan.range(e);
      double ox = pose.x() + c * scan.originX(e) - s * scan.originY(e);
      double oy = pose.y() + s * scan.originX(e) + c * scan.originY(e);
      double nearest = Double.MAX_VALUE;
      for (int a = 0; a < k; a++) {
        // The arc points lie on the cone's rays at the echo's range.
        double ex = pose.x() + c * scan.arcX(e, a) - s * scan.arcY(e, a);
        double ey = pose.y() + s * scan.arcX(e, a) + c * scan.arcY(e, a);
        double dx = (ex - ox) / range;
        double dy = (ey - oy) / range;
        nearest = Math.min(nearest, trace(field, ox, oy, dx, dy, range + matchDistance));
      }
      if (Math.abs(nearest - range) <= matchDistance) {
        matched++;
      }
    }
    return (double) matched / m;
  }

  /** Distance along a ray to the first mapped surface, or MAX_VALUE if none within limit. */
  private static double trace(
      LikelihoodField field, double ox, double oy, double dx, double dy, double limit) {
    double res = field.spec().res();
    double t = res;
    while (t <= limit) {
      double d = field.distanceAt(ox + dx * t, oy + dy * t);
      if (d < 0.75 * res) {
        return t;
      }
      t += Math.max(0.5 * res, d - 0.75 * res);
    }
    return Double.MAX_VALUE;
  }
}
