package org.jaria.range;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;

/**
 * The robot's sonar ring as a range device (ARIA's {@code ArSonarDevice}). Each cycle it takes the
 * sonar readings that are new in that cycle: the current buffer holds the latest reading of every
 * transducer; the cumulative buffer collects readings and forgets them when a newer reading sees
 * through them, when they are far from the robot, or when they get old.
 *
 * <p>Readings at or beyond the maximum range (5000 mm: "no echo") are not obstacles and are never
 * stored.
 */
public class ArSonarDevice extends ArRangeDevice {

  /** Half the opening of a sonar cone, degrees: readings inside it are cleaned by a new echo. */
  public static final double CONE_HALF_ANGLE = 15;

  private volatile double cumulativeInsertMaxDist = 3000;
  private volatile double cumulativeMaxDist = 8000;
  private volatile double filterNearDist = 50;
  private volatile double cleanDist = 75;
  private volatile long maxAgeMs;

  /** A sonar device with ARIA's defaults: range 5000 mm, 24 current and 64 cumulative points. */
  public ArSonarDevice() {
    this("sonar", 24, 64);
  }

  /** A sonar device with buffers of the given sizes. */
  public ArSonarDevice(String name, int currentSize, int cumulativeSize) {
    super(name, 5000, currentSize, cumulativeSize);
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    r.addSensorInterpTask(getName(), 50, this::processReadings);
  }

  /** Readings farther than this are not added to the cumulative buffer, mm (default 3000). */
  public void setCumulativeInsertMaxDist(double mm) {
    cumulativeInsertMaxDist = mm;
  }

  /** Cumulative readings farther than this from the robot are dropped, mm (default 8000). */
  public void setMaxDistToKeepCumulative(double mm) {
    cumulativeMaxDist = mm;
  }

  /** Cumulative readings older than this are dropped, ms (default 0: never). */
  public void setMaxSecondsToKeepCumulative(int seconds) {
    maxAgeMs = TimeUnit.SECONDS.toMillis(seconds);
  }

  /** A new cumulative reading this close to an old one replaces it, mm (default 50). */
  public void setFilterNearDist(double mm) {
    filterNearDist = mm;
  }

  /** Takes the readings that are new this cycle. Runs as a sensor-interpretation task. */
  public void processReadings() {
    ArRobot r = robot;
    if (r == null) {
      return;
    }
    long counter = r.getCounter();
    long now = r.getClock().nanoTime();
    ArPose pose = r.getPose();
    synchronized (this) {
      currentBuffer.clear();
      for (int i = 0; i < r.getNumSonar(); i++) {
        ArSensorReading s = r.getSonarReading(i);
        if (s == null || s.range() < 0) {
          continue;
        }
        if (s.range() < getMaxRange()) {
          currentBuffer.addReading(s.x(), s.y(), s.timeTaken());
        }
        if (s.isNew(counter)) {
          addCumulative(s);
        }
      }
      double maxDist2 = cumulativeMaxDist * cumulativeMaxDist;
      long maxAgeNanos = TimeUnit.MILLISECONDS.toNanos(maxAgeMs);
      cumulativeBuffer.removeIf(
          (x, y, t) -> {
            double dx = x - pose.x();
            double dy = y - pose.y();
            return dx * dx + dy * dy > maxDist2 || (maxAgeNanos > 0 && now - t > maxAgeNanos);
          });
    }
  }

  /** Cleans what this reading sees through, then adds the reading if it is an obstacle. */
  @GuardedBy("this")
  private void addCumulative(ArSensorReading s) {
    ArPose taken = s.poseTaken();
    double r = Math.toRadians(taken.th());
    double sx = taken.x() + Math.cos(r) * s.sensorX() - Math.sin(r) * s.sensorY();
    double sy = taken.y() + Math.sin(r) * s.sensorX() + Math.cos(r) * s.sensorY();
    double beam = taken.th() + s.sensorTh();
    double clearTo = s.range() - cleanDist;
    cumulativeBuffer.removeIf(
        (x, y, t) -> {
          double dx = x - sx;
          double dy = y - sy;
          double d = Math.hypot(dx, dy);
          if (d >= clearTo) {
            return false;
          }
          double a = ArMath.subAngle(Math.toDegrees(Math.atan2(dy, dx)), beam);
          return Math.abs(a) <= CONE_HALF_ANGLE;
        });
    if (s.range() < getMaxRange() && s.range() <= cumulativeInsertMaxDist) {
      cumulativeBuffer.addReadingConditional(s.x(), s.y(), s.timeTaken(), filterNearDist);
    }
  }
}
