package org.jaria.mapping;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jaria.geom.ArPose;

/**
 * The poses of the pose graph and what each keeps: the log's odometry pose, the distance driven to
 * it, and its scan's points (until they are let go as redundant). The pose estimates live in the
 * {@link PoseGraph}; this class adds what the builder needs beside them. Primitive arrays, grown by
 * doubling.
 */
final class Nodes {

  final PoseGraph graph = new PoseGraph();
  private final int keptResolution;
  private double[] odoX = new double[256];
  private double[] odoY = new double[256];
  private double[] odoTh = new double[256];
  private double[] travel = new double[256];
  private double[] time = new double[256];
  private final List<ScanPoints> points = new ArrayList<>();

  /** Points let go with pruned poses, in this pose's frame: cells of the map's resolution. */
  private final List<CellCounts> kept = new ArrayList<>();

  /** The map cells (where the estimates were then) of every point kept of pruned poses. */
  private final CellCounts folded = new CellCounts(1 << 12);

  private long pointBytes;
  private int withPoints;

  /** Nodes whose pruned poses' points are kept in cells of {@code keptResolution} mm. */
  Nodes(int keptResolution) {
    this.keptResolution = keptResolution;
  }

  /** Adds a node at the estimated pose; returns its index. */
  int add(ArPose estimate, ArPose odometry, double travelMm, double timeSec, ScanPoints pts) {
    int i = graph.addNode(estimate.x(), estimate.y(), estimate.th());
    if (i == odoX.length) {
      int n = i * 2;
      odoX = Arrays.copyOf(odoX, n);
      odoY = Arrays.copyOf(odoY, n);
      odoTh = Arrays.copyOf(odoTh, n);
      travel = Arrays.copyOf(travel, n);
      time = Arrays.copyOf(time, n);
    }
    odoX[i] = odometry.x();
    odoY[i] = odometry.y();
    odoTh[i] = odometry.th();
    travel[i] = travelMm;
    time[i] = timeSec;
    points.add(pts);
    kept.add(null);
    pointBytes += pts.bytes();
    withPoints++;
    return i;
  }

  int size() {
    return graph.size();
  }

  ArPose estimate(int i) {
    return new ArPose(graph.xMm(i), graph.yMm(i), graph.thDeg(i));
  }

  ArPose odometry(int i) {
    return new ArPose(odoX[i], odoY[i], odoTh[i]);
  }

  double travel(int i) {
    return travel[i];
  }

  double time(int i) {
    return time[i];
  }

  /** The node's points, or null if they were let go. */
  ScanPoints points(int i) {
    return points.get(i);
  }

  /** Lets go of node i's points (another node shows the same place). */
  void dropPoints(int i) {
    ScanPoints p = points.get(i);
    if (p != null) {
      pointBytes -= p.bytes();
      withPoints--;
      points.set(i, null);
    }
  }

  /**
   * Lets go of node {@code i}'s scan but keeps what it saw within the map range: its points become
   * cells of the kept resolution in the frame of node {@code into}, the older pose of the same
   * place it was found next to, so that when the graph moves that pose (a loop closure) they move
   * with it. A cell keeps how many readings fell in it, so the map can still tell a stray reading
   * from a surface.
   */
  void foldPoints(int i, int into) {
    int res = keptResolution;
    ScanPoints p = points.get(i);
    if (p == null || into == i) {
      return;
    }
    CellCounts target = kept.get(into);
    if (target == null) {
      target = new CellCounts(256);
      kept.set(into, target);
    }
    long before = target.bytes() + folded.bytes();
    double ti = graph.thRad(i);
    double ci = Math.cos(ti);
    double si = Math.sin(ti);
    // pose i in the frame of pose into
    double tj = graph.thRad(into);
    double cj = Math.cos(tj);
    double sj = Math.sin(tj);
    double dx = graph.xMm(i) - graph.xMm(into);
    double dy = graph.yMm(i) - graph.yMm(into);
    double rx = cj * dx + sj * dy;
    double ry = -sj * dx + cj * dy;
    double c = Math.cos(ti - tj);
    double s = Math.sin(ti - tj);
    for (int k = 0; k < p.count; k++) {
      if (!p.inMapRange[k]) {
        continue;
      }
      double lx = rx + c * p.px[k] - s * p.py[k];
      double ly = ry + s * p.px[k] + c * p.py[k];
      int cx = (int) Math.floor(lx / res);
      int cy = (int) Math.floor(ly / res);
      if (target.get(cx, cy) > 0) {
        target.add(cx, cy, 1);
        continue;
      }
      // a cell another pose already keeps (where the estimates are now) is not kept twice: a
      // place driven past on every lap would otherwise gather a copy per lap
      double gx = graph.xMm(i) + ci * p.px[k] - si * p.py[k];
      double gy = graph.yMm(i) + si * p.px[k] + ci * p.py[k];
      if (folded.add((int) Math.floor(gx / res), (int) Math.floor(gy / res), 1) == 0) {
        target.add(cx, cy, 1);
      }
    }
    pointBytes += target.bytes() + folded.bytes() - before;
    // nothing was folded into pose i (only older poses, already past pruning, receive points)
    dropPoints(i);
  }

  /** The size of the kept cells, mm. */
  int keptResolution() {
    return keptResolution;
  }

  /** The cells node i keeps of pruned poses (its frame), or null. */
  CellCounts keptCells(int i) {
    return kept.get(i);
  }

  /** Bytes of scan points held. */
  long pointBytes() {
    return pointBytes;
  }

  /** Nodes still holding points. */
  int withPoints() {
    return withPoints;
  }

  /** Squared distance between the estimates of nodes i and j, mm². */
  double distanceSq(int i, int j) {
    double dx = graph.xMm(i) - graph.xMm(j);
    double dy = graph.yMm(i) - graph.yMm(j);
    return dx * dx + dy * dy;
  }

  /**
   * Adds node {@code i}'s points to {@code index} in the map frame.
   *
   * @return whether the node had points
   */
  boolean addPoints(int i, PointIndex index) {
    ScanPoints p = points.get(i);
    if (p == null) {
      return false;
    }
    double t = graph.thRad(i);
    double c = Math.cos(t);
    double s = Math.sin(t);
    double x = graph.xMm(i);
    double y = graph.yMm(i);
    for (int k = 0; k < p.count; k++) {
      double lx = p.px[k];
      double ly = p.py[k];
      index.add(x + c * lx - s * ly, y + s * lx + c * ly);
    }
    return true;
  }
}
