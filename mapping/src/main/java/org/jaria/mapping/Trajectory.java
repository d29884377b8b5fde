package org.jaria.mapping;

import java.util.Arrays;
import org.jaria.geom.ArPose;

/**
 * The robot's path through a built map: for every scan of the log that was used, its number, its
 * time, the odometry pose the log gave and the corrected pose in the map. Primitive arrays, so a
 * long log costs about 60 bytes a scan.
 */
public final class Trajectory {

  private final int[] ids;
  private final double[] times;
  private final double[] odo;
  private final double[] pose;
  private final int size;

  private Trajectory(int[] ids, double[] times, double[] odo, double[] pose, int size) {
    this.ids = ids;
    this.times = times;
    this.odo = odo;
    this.pose = pose;
    this.size = size;
  }

  /** Number of scans on the path. */
  public int size() {
    return size;
  }

  /** The log's number of scan {@code i}. */
  public int scanId(int i) {
    return ids[check(i)];
  }

  /** Seconds since logging started at scan {@code i}. */
  public double time(int i) {
    return times[check(i)];
  }

  /** The odometry pose the log gave for scan {@code i}. */
  public ArPose odometry(int i) {
    int k = 3 * check(i);
    return new ArPose(odo[k], odo[k + 1], odo[k + 2]);
  }

  /** The corrected pose of scan {@code i} in the map. */
  public ArPose pose(int i) {
    int k = 3 * check(i);
    return new ArPose(pose[k], pose[k + 1], pose[k + 2]);
  }

  private int check(int i) {
    if (i < 0 || i >= size) {
      throw new IndexOutOfBoundsException("scan " + i + " of " + size);
    }
    return i;
  }

  /** Collects the scans as they come; the corrected poses are made once the graph is final. */
  static final class Builder {
    private int[] ids = new int[256];
    private double[] times = new double[256];
    private double[] odo = new double[768];
    private int[] node = new int[256];
    private double[] rel = new double[768];
    private int size;

    void add(int id, double time, ArPose odometry, int nodeIndex, ArPose fromNode) {
      if (size == ids.length) {
        int n = size * 2;
        ids = Arrays.copyOf(ids, n);
        times = Arrays.copyOf(times, n);
        node = Arrays.copyOf(node, n);
        odo = Arrays.copyOf(odo, 3 * n);
        rel = Arrays.copyOf(rel, 3 * n);
      }
      ids[size] = id;
      times[size] = time;
      node[size] = nodeIndex;
      odo[3 * size] = odometry.x();
      odo[3 * size + 1] = odometry.y();
      odo[3 * size + 2] = odometry.th();
      rel[3 * size] = fromNode.x();
      rel[3 * size + 1] = fromNode.y();
      rel[3 * size + 2] = fromNode.th();
      size++;
    }

    Trajectory build(Nodes nodes) {
      double[] pose = new double[3 * size];
      for (int i = 0; i < size; i++) {
        ArPose r = new ArPose(rel[3 * i], rel[3 * i + 1], rel[3 * i + 2]);
        ArPose p = Poses.compose(nodes.estimate(node[i]), r);
        pose[3 * i] = p.x();
        pose[3 * i + 1] = p.y();
        pose[3 * i + 2] = p.th();
      }
      return new Trajectory(
          Arrays.copyOf(ids, size),
          Arrays.copyOf(times, size),
          Arrays.copyOf(odo, 3 * size),
          pose,
          size);
    }
  }
}
