package org.jaria.arnl;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.arnl.plan.AStarPlanner;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.PathSmoother;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.range.ArSonarDevice;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/** Test worlds: a map, a p3dx-sh with drifting odometry, in lockstep. */
final class SimSetup {

  private SimSetup() {}

  /** The Columbia reference map (the test copy in aria-core). */
  static ArMap columbia() {
    try {
      return ArMap.readFile(
          Path.of(
              "..", "aria-core", "src", "test", "resources", "reference", "maps", "columbia.map"));
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    } catch (MapFormatException e) {
      throw new IllegalStateException(e);
    }
  }

  /** A world on {@code map} with one robot (at the map's home) connected in lockstep. */
  static SimulatedRobot start(ArMap map, long seed) {
    return start(map, seed, null);
  }

  /** As {@link #start(ArMap, long)}, the robot at {@code pose} (null: the map's home). */
  static SimulatedRobot start(ArMap map, long seed, ArPose pose) {
    SimWorld world =
        SimWorld.create(
            map,
            SimOptions.builder()
                .seed(seed)
                .odometryError(OdometryError.random(0.02, 0.02))
                .build());
    RobotOptions o = RobotOptions.of("p3dx-sh");
    SimRobot r = world.addRobot(pose == null ? o : o.withStartPose(pose));
    SimulatedRobot sim = SimulatedRobot.connect(world, r);
    sim.robot().addRangeDevice(new ArSonarDevice());
    sim.robot().enableMotors();
    return sim;
  }

  /**
   * Waypoints (every half metre) of a planned path from the map's home to the goal called {@code
   * goal}, for driving by the true pose.
   */
  static List<ArPose> truePath(ArMap map, String goal) {
    return truePath(map, map.findHomePose().orElseThrow(), goal);
  }

  /** As {@link #truePath(ArMap, String)}, from {@code home}. */
  static List<ArPose> truePath(ArMap map, ArPose home, String goal) {
    NavigationMap nav = NavigationMap.build(map, 100, 300, 1000, 4);
    ArPose g = map.findMapObject(goal).orElseThrow().pose();
    int[] cells =
        new AStarPlanner()
            .plan(
                nav.grid(),
                nav.grid().spec().indexOf(home.x(), home.y()),
                nav.grid().spec().indexOf(g.x(), g.y()));
    PlannedPath p = PathSmoother.smooth(cells, nav.grid(), home.x(), home.y(), g.x(), g.y());
    List<ArPose> route = new ArrayList<>();
    for (int i = 5; i < p.size(); i += 5) {
      route.add(new ArPose(p.x(i), p.y(i)));
    }
    route.add(g);
    return route;
  }

  /** Closes the robot and its world. */
  static void stop(SimulatedRobot sim) {
    sim.close();
    sim.world().close();
  }
}
