package org.jaria.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.jaria.action.ArActionTriangleDriveTo;
import org.jaria.action.ArActionTriangleDriveTo.State;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

/**
 * ArActionTriangleDriveTo against the simulator's laser, on ARIA's own triangle.map: the robot
 * starts two metres from a docking triangle (a 135° vertex with sides of about 250 mm), finds it in
 * the laser's sweeps and stops in front of the vertex.
 */
class TriangleDriveToScenarioTest {

  /** The vertex of the triangle in triangle.map, where its 250 mm and 254 mm sides meet. */
  private static final ArPose VERTEX = new ArPose(4970, 5655);

  private static Path triangleMap() {
    // The system tests run in src/test; the reference maps live in aria-core's test resources.
    for (String base : new String[] {"../../aria-core", "../aria-core", "aria-core"}) {
      Path p = Path.of(base, "src/test/resources/reference/maps/triangle.map");
      if (Files.exists(p)) {
        return p;
      }
    }
    throw new IllegalStateException("triangle.map not found from " + Path.of("").toAbsolutePath());
  }

  @Test
  void findsTheTriangleWithTheRobotsLaserAndStopsInFrontOfIt() throws Exception {
    try (SimWorld world = SimWorld.load(triangleMap(), SimOptions.builder().seed(2).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        sim.robot().addRangeDevice(new ArSimulatedLaser());
        ArActionTriangleDriveTo drive =
            new ArActionTriangleDriveTo("triangleDriveTo", 400, 1000, 200, 100, 30);
        sim.robot().addAction(drive, 50);
        drive.activate();
        sim.robot().enableMotors();
        assertTrue(
            sim.runUntil(
                () ->
                    drive.getState() == State.STATE_SUCCEEDED
                        || drive.getState() == State.STATE_FAILED,
                Duration.ofSeconds(90)),
            "still " + drive.getState() + " after 90 s");
        assertEquals(State.STATE_SUCCEEDED, drive.getState());
        ArPose end = r.getTruePose();
        double dist = end.findDistanceTo(VERTEX);
        assertEquals(400, dist, 120, "stopped about 400 mm from the vertex, at " + end);
        double facing = end.findAngleTo(VERTEX) - end.th();
        assertEquals(0, org.jaria.geom.ArMath.fixAngle(facing), 15, "facing the vertex");
      }
    }
  }
}
