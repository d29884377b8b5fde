package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.io.StringWriter;
import org.jaria.action.ArActionGroupWander;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapPoints;
import org.jaria.range.ArSensorReading;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

/**
 * The sonar sketch on the simulator: a sonar-only P3-DX wanders the hall (seeded, odometry error
 * on), and the sketch's occupied cells are scored against the true walls.
 */
class SonarSketchTest {

  /** Wanders {@code map} for {@code seconds} and sketches what the sonar saw. */
  static SonarSketch sketch(ArMap map, long seed, int seconds) {
    SimWorld world =
        SimWorld.create(
            map,
            SimOptions.builder()
                .seed(seed)
                .odometryError(OdometryError.random(0.02, 0.02))
                .build());
    ArPose home = map.findHomePose().orElse(ArPose.ORIGIN);
    SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(home));
    SimulatedRobot sim = SimulatedRobot.connect(world, r);
    SonarSketch s = new SonarSketch();
    try {
      ArRobot robot = sim.robot();
      robot.addRangeDevice(new ArSonarDevice());
      robot.moveTo(home); // odometry starts where the robot is, as a user would set it
      robot.addUserTask(
          "sketch",
          60,
          () -> {
            for (int i = 0; i < robot.getNumSonar(); i++) {
              ArSensorReading e = robot.getSonarReading(i);
              if (e != null && e.isNew(robot.getCounter())) {
                s.add(e.getPoseTaken(), e.getSensorX(), e.getSensorY(), e.getSensorTh(), e.range());
              }
            }
          });
      new ArActionGroupWander(robot).activateExclusive();
      robot.enableMotors();
      sim.runMillis(seconds * 1000L);
      return s;
    } finally {
      sim.close();
      world.close();
    }
  }

  /** The share of {@code xy}'s points within {@code tol} mm of a wall of {@code truth}. */
  static double nearWalls(int[] xy, ArMap truth, double tol) {
    ArMapPoints pts = truth.getPoints();
    int near = 0;
    for (int i = 0; i < xy.length / 2; i++) {
      double x = xy[2 * i];
      double y = xy[2 * i + 1];
      double best = Double.MAX_VALUE;
      for (ArLineSegment l : truth.getLines()) {
        best = Math.min(best, MapQuality.distance(l, x, y));
      }
      for (int k = 0; k < pts.size() && best > tol; k++) {
        best = Math.min(best, Math.hypot(pts.x(k) - x, pts.y(k) - y));
      }
      if (best <= tol) {
        near++;
      }
    }
    return xy.length == 0 ? 0 : near / (xy.length / 2.0);
  }

  @Test
  void occupiedCellsLieNearTheTrueWalls() throws Exception {
    ArMap hall = ArMap.loadBundled("hall");
    SonarSketch s = sketch(hall, 11, 180);
    int[] cells = s.occupied();
    double near = nearWalls(cells, hall, 250);
    System.out.printf(
        "sonar sketch of hall, 180 s: %d echoes, %d occupied cells, %.1f %% within 250 mm%n",
        s.readings(), cells.length / 2, 100 * near);
    assertTrue(cells.length / 2 >= 100, "cells: " + cells.length / 2);
    assertTrue(near >= 0.70, "share near a true wall: " + near); // 76 % measured

    StringWriter w = new StringWriter();
    s.writeMap(w);
    ArMap m = ArMap.read(new StringReader(w.toString()), "sketch");
    assertEquals(cells.length / 2, m.getPoints().size());
    assertEquals(0, m.getLines().size(), "a sketch has no lines to localize on");
    assertTrue(w.toString().contains("not a map for localization"), "labelled");
  }

  @Test
  void nonsenseReadingsAreIgnoredAndFarPosesRefused() {
    SonarSketch s = new SonarSketch();
    s.add(new ArPose(0, 0, 0), 0, 0, 0, Double.NaN);
    s.add(new ArPose(Double.NaN, 0, 0), 0, 0, 0, 1000);
    s.add(new ArPose(0, 0, 0), 0, 0, 0, -1);
    assertEquals(0, s.readings());
    s.add(new ArPose(0, 0, 0), 0, 0, 0, 5000);
    assertEquals(0, s.readings(), "beyond the range: no echo, free space only");
    assertTrue(s.oddsAt(1000, 0) < 0, "free before it");
    s.add(new ArPose(0, 0, 0), 0, 0, 0, 1000);
    s.add(new ArPose(0, 0, 0), 0, 0, 0, 1000);
    assertTrue(s.oddsAt(1000, 0) > 0, "the echo's cell");
    assertThrows(IllegalStateException.class, () -> s.add(new ArPose(1e9, 1e9, 0), 0, 0, 0, 1000));
  }
}
