package org.jaria.apps.simview;

import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/**
 * {@code simview --demo}: a built-in client that wanders a simulated robot around with its sonar,
 * so the view has something to show without an ARIA program. Drives forward, and turns towards the
 * freer side when something is closer than {@value #TURN_MM} mm ahead. Runs in the robot's task
 * cycle (on the world's thread).
 */
final class DemoDriver {

  /** Turn when an obstacle in front is closer than this, mm. */
  static final int TURN_MM = 1000;

  private final ArRobot robot;
  private int turning;

  private DemoDriver(ArRobot robot) {
    this.robot = robot;
  }

  /**
   * Connects a client to {@code simRobot} (in lockstep with the world) and starts wandering.
   *
   * @return the client; close it before the world
   */
  static SimulatedRobot start(SimWorld world, SimRobot simRobot) {
    SimulatedRobot client = SimulatedRobot.connect(world, simRobot);
    ArRobot r = client.robot();
    DemoDriver d = new DemoDriver(r);
    r.enableMotors();
    r.addUserTask("demo wander", 50, d::cycle);
    return client;
  }

  private void cycle() {
    int front = robot.getClosestSonarRange(-35, 35);
    boolean blocked = front > 0 && front < TURN_MM;
    if (!blocked) {
      turning = 0;
      robot.setVel(350);
      robot.setRotVel(0);
      return;
    }
    if (turning == 0) {
      int left = range(robot.getClosestSonarRange(35, 100));
      int right = range(robot.getClosestSonarRange(-100, -35));
      turning = left >= right ? 1 : -1;
    }
    robot.setVel(front < TURN_MM / 2 ? 0 : 100);
    robot.setRotVel(35 * turning);
  }

  private static int range(int r) {
    return r < 0 ? Integer.MAX_VALUE : r;
  }
}
