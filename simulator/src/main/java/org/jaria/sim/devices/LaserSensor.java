package org.jaria.sim.devices;

import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;
import org.jaria.sim.robot.RobotModel;

/** What an emulated laser measures: ranges over a fan of directions. */
public interface LaserSensor {

  /** The farthest range the sensor reports, mm; a ray that hits nothing reads this. */
  double maxRange();

  /**
   * Measures {@code count} ranges, mm, the first at {@code firstDeg} from the laser's front and
   * then every {@code incDeg} counter-clockwise.
   */
  double[] ranges(double firstDeg, double incDeg, int count);

  /**
   * The laser of a simulated robot, as mounted by its model, measuring the world from the robot's
   * true pose (noise-free, so tests can compare with the geometry).
   */
  static LaserSensor of(SimRobot robot) {
    RobotModel m = robot.getModel();
    double max = m.getLaserMaxRange();
    return new LaserSensor() {
      @Override
      public double maxRange() {
        return max;
      }

      @Override
      public double[] ranges(double firstDeg, double incDeg, int count) {
        ArPose p = robot.getTruePose();
        double c = Math.cos(p.getThRad());
        double s = Math.sin(p.getThRad());
        double x = p.x() + c * m.getLaserX() - s * m.getLaserY();
        double y = p.y() + s * m.getLaserX() + c * m.getLaserY();
        double th = p.th() + m.getLaserTh();
        double[] r = new double[count];
        for (int i = 0; i < count; i++) {
          double d = robot.getWorld().castRay(x, y, th + firstDeg + i * incDeg, max, robot);
          r[i] = Double.isFinite(d) ? Math.min(d, max) : max;
        }
        return r;
      }
    };
  }
}
