package org.jaria.tools.sim;

import org.jaria.map.ArMap;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/**
 * The simulated robot the drive-and-record commands ({@code jaria laser log --sim}, {@code jaria
 * map sketch --sim}) use: a p3dx-sh in lockstep on a map file, its world seeded and its odometry
 * drifting as the user asked, so a drive can be repeated exactly.
 */
public final class SeededDrive {

  private SeededDrive() {}

  /**
   * A p3dx-sh connected in lockstep to a new world on {@code map}.
   *
   * @param odometryError the {@code --odometry-error} text ({@link OdometryError#parse})
   */
  public static SimulatedRobot p3dx(ArMap map, long seed, String odometryError) {
    SimWorld world =
        SimWorld.create(
            map,
            SimOptions.builder()
                .seed(seed)
                .odometryError(OdometryError.parse(odometryError))
                .build());
    return SimulatedRobot.connect(world, world.addRobot(RobotOptions.of("p3dx-sh")));
  }
}
