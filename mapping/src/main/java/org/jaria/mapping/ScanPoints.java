package org.jaria.mapping;

import java.util.Arrays;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LoggedScan;

/**
 * One scan's readings in the robot's frame: the points (every usable reading within the match
 * range, at most one per map cell, in sweep order) and the match points, a sparser subset at least
 * {@link #MATCH_SPACING_MM} apart along the sweep that is moved onto the map by the scan matcher.
 * Readings without echo, at the no-echo range, closer than the minimum range or damaged are left
 * out.
 */
final class ScanPoints {

  /** Match points are at least this far apart along the sweep, mm. */
  static final double MATCH_SPACING_MM = 40;

  final double[] px;
  final double[] py;
  final boolean[] inMapRange;
  final int count;
  final double[] kx;
  final double[] ky;
  final int matchCount;

  private ScanPoints(double[] px, double[] py, boolean[] inMap, double[] kx, double[] ky) {
    this.px = px;
    this.py = py;
    this.inMapRange = inMap;
    this.count = px.length;
    this.kx = kx;
    this.ky = ky;
    this.matchCount = kx.length;
  }

  /** Approximate bytes held. */
  long bytes() {
    return 17L * count + 16L * matchCount + 64;
  }

  /**
   * The points of {@code s}, for a laser mounted at {@code mount} on the robot.
   *
   * @param filter the log's no-echo filter (it learns from this scan)
   */
  static ScanPoints of(LoggedScan s, ArPose mount, MapBuilderParams p, NoEchoFilter filter) {
    filter.learn(s);
    int n = s.size();
    double c = Math.cos(mount.getThRad());
    double sn = Math.sin(mount.getThRad());
    CellCounts cells = new CellCounts(n);
    double res = p.resolutionMm();
    double[] px = new double[n];
    double[] py = new double[n];
    boolean[] inMap = new boolean[n];
    int m = 0;
    for (int i = 0; i < n; i++) {
      if (!s.hasEcho(i)) {
        continue;
      }
      double r = s.range(i);
      if (r < p.minRangeMm() || r > p.matchRangeMm() || filter.isNoEcho(r)) {
        continue;
      }
      double lx = s.x(i);
      double ly = s.y(i);
      double x = mount.x() + c * lx - sn * ly;
      double y = mount.y() + sn * lx + c * ly;
      if (cells.add((int) Math.floor(x / res), (int) Math.floor(y / res), 1) == 0) {
        px[m] = x;
        py[m] = y;
        inMap[m] = r <= p.mapRangeMm();
        m++;
      }
    }
    double[] kx = new double[m];
    double[] ky = new double[m];
    int k = 0;
    double lastX = 0;
    double lastY = 0;
    double spacing2 = MATCH_SPACING_MM * MATCH_SPACING_MM;
    for (int i = 0; i < m; i++) {
      double dx = px[i] - lastX;
      double dy = py[i] - lastY;
      if (k == 0 || dx * dx + dy * dy >= spacing2) {
        kx[k] = px[i];
        ky[k] = py[i];
        lastX = px[i];
        lastY = py[i];
        k++;
      }
    }
    return new ScanPoints(
        Arrays.copyOf(px, m),
        Arrays.copyOf(py, m),
        Arrays.copyOf(inMap, m),
        Arrays.copyOf(kx, k),
        Arrays.copyOf(ky, k));
  }
}
