package org.jaria.range;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.robot.ArRobot;

/**
 * The bump rings as a range device (ARIA's {@code ArBumpers}): while a bumper is pressed, a reading
 * sits where that bumper is on the robot's edge, so obstacle-avoidance code that looks at range
 * devices also backs away from what it touched. Front bumpers are spread evenly over the front arc
 * (135° by default), rear bumpers over the rear arc. Readings stay in the current buffer for a few
 * seconds after the bump, since the robot usually backs away from the contact at once.
 */
public class ArBumpers extends ArRangeDevice {

  private final double angleRange;
  private final long keepNanos;

  /** Bumpers with ARIA's defaults: 135° arcs, readings kept 15 s. */
  public ArBumpers() {
    this("bumpers", 135, 15);
  }

  /** Bumpers spread over {@code angleRange} degrees, readings kept {@code keepSeconds}. */
  public ArBumpers(String name, double angleRange, int keepSeconds) {
    super(name, 5000, 30, 30);
    this.angleRange = angleRange;
    this.keepNanos = TimeUnit.SECONDS.toNanos(keepSeconds);
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    r.addSensorInterpTask(getName(), 49, this::processReadings);
  }

  /** Direction of bumper {@code i} of {@code n} on the front ring, degrees (0 ahead). */
  double frontAngle(int i, int n) {
    // Bumper 0 is the leftmost when the ring is seen from above, facing forward.
    return angleRange / 2 - (i + 0.5) * angleRange / n;
  }

  /** Adds a reading for every pressed bumper; drops old readings. Runs each cycle. */
  public void processReadings() {
    ArRobot r = robot;
    if (r == null) {
      return;
    }
    ArRobotParams p = r.getRobotParams();
    long now = r.getClock().nanoTime();
    int front = r.getFrontBumpers();
    int rear = r.getRearBumpers();
    ArTransform toGlobal = r.getToGlobalTransform();
    synchronized (this) {
      currentBuffer.removeIf((x, y, t) -> now - t > keepNanos);
      cumulativeBuffer.removeIf((x, y, t) -> now - t > keepNanos);
      int nf = Math.max(1, p.getNumFrontBumpers());
      for (int i = 0; i < nf && i < 7; i++) {
        if ((front & (1 << i)) != 0) {
          add(toGlobal, frontAngle(i, nf), p.getRobotLengthFront(), p.getRobotWidth(), now);
        }
      }
      int nr = Math.max(1, p.getNumRearBumpers());
      for (int i = 0; i < nr && i < 7; i++) {
        if ((rear & (1 << i)) != 0) {
          add(toGlobal, 180 + frontAngle(i, nr), p.getRobotLengthRear(), p.getRobotWidth(), now);
        }
      }
    }
  }

  @GuardedBy("this")
  private void add(ArTransform toGlobal, double angleDeg, double length, double width, long now) {
    double a = Math.toRadians(angleDeg);
    // A point on the ellipse through the robot's front (or rear) and sides.
    double lx = length * Math.cos(a);
    double ly = (width / 2) * Math.sin(a);
    double gx = toGlobal.transformX(lx, ly);
    double gy = toGlobal.transformY(lx, ly);
    currentBuffer.addReadingConditional(gx, gy, now, 10);
    cumulativeBuffer.addReadingConditional(gx, gy, now, 10);
  }
}
