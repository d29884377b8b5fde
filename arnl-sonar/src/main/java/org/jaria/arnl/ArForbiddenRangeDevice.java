package org.jaria.arnl;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.range.ArRangeDevice;
import org.jaria.robot.ArRobot;

/**
 * Turns the map's forbidden lines and the edges of its forbidden areas into range readings (ARIA's
 * {@code ArForbiddenRangeDevice}), so that anything that avoids range-device readings —
 * obstacle-avoiding actions, the path planner's local planner — also keeps out of forbidden places,
 * as if they were walls only the robot can see. Each cycle the current buffer holds the points of
 * those edges (every {@code distanceIncrement} mm) within the device's range of the robot's
 * (localized) pose.
 */
public class ArForbiddenRangeDevice extends ArRangeDevice {

  private final double[] px;
  private final double[] py;
  private volatile boolean enabled = true;

  /** Forbidden edges of {@code map} sampled every 100 mm, seen up to 4 m away. */
  public ArForbiddenRangeDevice(ArMap map) {
    this(map, 100, 4000, "forbidden");
  }

  /**
   * Forbidden edges of {@code map}.
   *
   * @param distanceIncrement spacing of the points along each edge, mm
   * @param maxRange points farther than this from the robot are left out, mm
   * @param name the device's name
   */
  public ArForbiddenRangeDevice(ArMap map, double distanceIncrement, double maxRange, String name) {
    super(name, maxRange, capacity(map, distanceIncrement), capacity(map, distanceIncrement));
    List<double[]> pts = new ArrayList<>();
    for (ArMapObject o : map.getMapObjects()) {
      if (!o.hasFromTo() || !o.type().startsWith("Forbidden")) {
        continue;
      }
      for (ArLineSegment s : o.getFromToSegments()) {
        int n = Math.max(1, (int) Math.ceil(s.length() / distanceIncrement));
        for (int k = 0; k <= n; k++) {
          double t = (double) k / n;
          pts.add(new double[] {s.x1() + (s.x2() - s.x1()) * t, s.y1() + (s.y2() - s.y1()) * t});
        }
      }
    }
    px = new double[pts.size()];
    py = new double[pts.size()];
    for (int i = 0; i < pts.size(); i++) {
      px[i] = pts.get(i)[0];
      py[i] = pts.get(i)[1];
    }
  }

  private static int capacity(ArMap map, double step) {
    if (!(step > 0)) {
      throw new IllegalArgumentException("distance increment must be positive, got " + step);
    }
    long n = 0;
    for (ArMapObject o : map.getMapObjects()) {
      if (o.hasFromTo() && o.type().startsWith("Forbidden")) {
        for (ArLineSegment s : o.getFromToSegments()) {
          n += (long) Math.ceil(s.length() / step) + 1;
        }
      }
    }
    return (int) Math.max(1, Math.min(100_000, n));
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    r.addSensorInterpTask(getName(), 47, this::processReadings);
  }

  /** Number of edge points (all of them, near or far). */
  public int getPointCount() {
    return px.length;
  }

  /** Starts producing readings (the default). */
  public void enable() {
    enabled = true;
  }

  /** Stops producing readings (and clears them). */
  public synchronized void disable() {
    enabled = false;
    currentBuffer.clear();
    cumulativeBuffer.clear();
  }

  /** Whether the device produces readings. */
  public boolean isEnabled() {
    return enabled;
  }

  /** Refreshes the readings around the robot's pose. Runs each cycle. */
  public void processReadings() {
    ArRobot r = robot;
    if (r == null) {
      return;
    }
    ArPose pose = r.getPose();
    long now = r.getClock().nanoTime();
    double range2 = getMaxRange() * getMaxRange();
    synchronized (this) {
      currentBuffer.clear();
      cumulativeBuffer.clear();
      if (!enabled) {
        return;
      }
      for (int i = 0; i < px.length; i++) {
        double dx = px[i] - pose.x();
        double dy = py[i] - pose.y();
        if (dx * dx + dy * dy <= range2) {
          currentBuffer.addReading(px[i], py[i], now);
          cumulativeBuffer.addReading(px[i], py[i], now);
        }
      }
    }
  }
}
