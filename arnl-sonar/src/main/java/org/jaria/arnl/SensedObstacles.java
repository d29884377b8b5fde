package org.jaria.arnl;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.SonarOccupancy;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.ArSensorReading;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/**
 * Gathers, each cycle, the obstacle points the local planner must avoid: cells of a rolling sonar
 * occupancy grid ({@link SonarOccupancy}) that hold an obstacle the map does not explain (cells
 * near a mapped wall are the wall, which the planner already knows exactly), plus the points of the
 * other range devices added to the task (bumpers, IRs, forbidden-range device). The grid is kept in
 * odometry coordinates, so localization corrections move its obstacles along. The points are {@link
 * GoalKeeper}'s, used under its lock (the field holding this is {@code @GuardedBy} it); the device
 * list may be changed from any thread.
 */
final class SensedObstacles {

  /** A range device and which of its buffers to use. */
  record Device(ArRangeDevice device, ArPathPlanningTask.RangeType type) {}

  private static final int MAX_POINTS = 1024;

  /** Echoes beyond this are treated as "no echo" by the occupancy grid, mm. */
  static final double ECHO_RANGE = 3000;

  private static final double OCCUPIED_THRESHOLD = 0.6;

  private final ArRobot robot;
  private final List<Device> devices = new CopyOnWriteArrayList<>();
  private final SonarOccupancy grid = new SonarOccupancy(10000, 50);
  private final long[] lastCounter = new long[64];
  private final double[] xs = new double[MAX_POINTS];
  private final double[] ys = new double[MAX_POINTS];
  private int n;

  SensedObstacles(ArRobot robot) {
    this.robot = robot;
    java.util.Arrays.fill(lastCounter, Long.MIN_VALUE);
  }

  void addDevice(ArRangeDevice d, ArPathPlanningTask.RangeType type) {
    devices.removeIf(e -> e.device() == d);
    if (type != ArPathPlanningTask.RangeType.NEITHER) {
      devices.add(new Device(d, type));
    }
  }

  void removeDevice(ArRangeDevice d) {
    devices.removeIf(e -> e.device() == d);
  }

  /**
   * Takes this cycle's new sonar readings into the occupancy grid.
   *
   * @param nav the map, to recognise echoes of mapped walls (null: no such check)
   * @param matchDistance an echo within this of the range the map predicts is the wall, mm
   */
  void noteSonar(NavigationMap nav, double matchDistance) {
    ArPose enc = robot.getEncoderPose();
    ArTransform toGlobal = robot.getEncoderTransform();
    grid.follow(enc.x(), enc.y());
    int ns = Math.min(robot.getNumSonar(), lastCounter.length);
    double half = Math.toRadians(ArSonarDevice.CONE_HALF_ANGLE);
    for (int i = 0; i < ns; i++) {
      ArSensorReading r = robot.getSonarReading(i);
      if (r == null || r.range() < 0 || r.counterTaken() == lastCounter[i]) {
        continue;
      }
      lastCounter[i] = r.counterTaken();
      ArPose at = r.encoderPoseTaken();
      double th = Math.toRadians(at.th());
      double c = Math.cos(th);
      double s = Math.sin(th);
      double sx = at.x() + c * r.sensorX() - s * r.sensorY();
      double sy = at.y() + s * r.sensorX() + c * r.sensorY();
      double axis = th + Math.toRadians(r.sensorTh());
      boolean explained = false;
      if (nav != null && r.range() < ECHO_RANGE) {
        double gx = toGlobal.transformX(sx, sy);
        double gy = toGlobal.transformY(sx, sy);
        double ga = axis + Math.toRadians(toGlobal.getTh());
        double expected = nav.expectedSonarRange(gx, gy, ga, half, r.range() + matchDistance);
        explained = Math.abs(expected - r.range()) <= matchDistance;
      }
      grid.addReading(sx, sy, axis, r.range(), ECHO_RANGE, half, explained);
    }
  }

  /**
   * Recomputes the obstacle points around {@code pose}.
   *
   * @param useSonar whether the sonar grid counts
   * @param range farthest obstacle considered, mm from the robot
   * @param matchDistance sonar obstacles this close to a mapped wall are the wall, mm
   */
  void collect(
      ArPose pose, NavigationMap nav, boolean useSonar, double range, double matchDistance) {
    n = 0;
    double range2 = range * range;
    if (useSonar) {
      ArTransform toGlobal = robot.getEncoderTransform();
      ArPose enc = toGlobal.inverse().doTransform(pose);
      grid.occupiedNear(
          enc.x(),
          enc.y(),
          range,
          OCCUPIED_THRESHOLD,
          (ex, ey) -> {
            double gx = toGlobal.transformX(ex, ey);
            double gy = toGlobal.transformY(ex, ey);
            if (nav.wallDistanceAt(gx, gy) > matchDistance) {
              add(gx, gy);
            }
          });
    }
    for (Device d : devices) {
      ArPathPlanningTask.RangeType t = d.type();
      if (t == ArPathPlanningTask.RangeType.CURRENT || t == ArPathPlanningTask.RangeType.BOTH) {
        addAll(d.device().getCurrentReadings(), pose, range2);
      }
      if (t == ArPathPlanningTask.RangeType.CUMULATIVE || t == ArPathPlanningTask.RangeType.BOTH) {
        addAll(d.device().getCumulativeReadings(), pose, range2);
      }
    }
  }

  /** Forgets what the sonar has seen. */
  void clearSonar() {
    grid.clear();
  }

  private void addAll(List<ArPose> pts, ArPose pose, double range2) {
    for (ArPose p : pts) {
      double dx = p.x() - pose.x();
      double dy = p.y() - pose.y();
      if (dx * dx + dy * dy <= range2) {
        add(p.x(), p.y());
      }
    }
  }

  private void add(double x, double y) {
    if (n < MAX_POINTS) {
      xs[n] = x;
      ys[n] = y;
      n++;
    }
  }

  int count() {
    return n;
  }

  double[] xs() {
    return xs;
  }

  double[] ys() {
    return ys;
  }
}
