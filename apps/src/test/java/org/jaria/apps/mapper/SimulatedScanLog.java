package org.jaria.apps.mapper;

import java.nio.file.Path;
import org.jaria.action.ArActionGroupWander;
import org.jaria.laser.ArLaserLogger;
import org.jaria.map.ArMap;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/**
 * A scan log recorded on the simulator in virtual time, as {@code jaria laser log --sim MAP} makes
 * it with its defaults: a p3dx-sh (seed 1, odometry drifting {@code random:0.02,0.02}) wanders with
 * ARIA's wander group, sonar to avoid obstacles and the simulator's laser, logged every 300 mm or
 * 25 degrees as sickLogger does. Built here from the libraries so that the map editor's tests need
 * no command line.
 */
final class SimulatedScanLog {

  private SimulatedScanLog() {}

  /**
   * Wanders {@code seconds} of simulated time on bundled map {@code map} and writes the log to
   * {@code file}.
   *
   * @return the number of scans logged
   */
  static int record(String map, double seconds, Path file) throws Exception {
    SimWorld world =
        SimWorld.create(
            ArMap.loadBundled(map),
            SimOptions.builder()
                .seed(1)
                .odometryError(OdometryError.parse("random:0.02,0.02"))
                .build());
    SimulatedRobot s = SimulatedRobot.connect(world, world.addRobot(RobotOptions.of("p3dx-sh")));
    try {
      ArRobot robot = s.robot();
      ArSimulatedLaser laser = new ArSimulatedLaser();
      robot.lock();
      try {
        robot.addRangeDevice(laser);
        robot.addRangeDevice(new ArSonarDevice());
      } finally {
        robot.unlock();
      }
      s.runMillis(1000);
      ArLaserLogger logger = new ArLaserLogger(robot, laser, 300, 25, file.toString());
      if (!logger.wasFileOpenedSuccessfully()) {
        logger.close();
        throw new IllegalStateException(logger.getFailure());
      }
      robot.lock();
      try {
        new ArActionGroupWander(robot).activateExclusive();
        robot.enableMotors();
      } finally {
        robot.unlock();
      }
      s.runMillis((long) (seconds * 1000));
      robot.stop();
      s.runMillis(500);
      logger.close();
      if (!logger.getFailure().isEmpty()) {
        throw new IllegalStateException(logger.getFailure());
      }
      return logger.getScanCount();
    } finally {
      s.close();
      world.close();
    }
  }
}
