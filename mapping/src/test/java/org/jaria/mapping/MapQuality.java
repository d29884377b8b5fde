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
