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
  private double[] odoX = new double[256];
  private double[] odoY = new double[256];
  private double[] odoTh = new double[256];
  private double[] travel = new double[256];
  private double[] time = new double[256];
  private final List<ScanPoints> points = new ArrayList<>();
  private long pointBytes;
  private int withPoints;

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
