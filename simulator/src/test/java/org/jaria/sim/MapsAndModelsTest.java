package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.world.WorldMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Worlds from real and bundled maps; robot models from parameter files. */
class MapsAndModelsTest {

  /** The reference maps, copied into aria-core's test resources. */
  static Path referenceMap(String name) {
    Path p = Path.of("../aria-core/src/test/resources/reference/maps", name);
    if (!Files.exists(p)) {
      p = Path.of("aria-core/src/test/resources/reference/maps", name);
    }
    return p;
  }

  @Test
  void columbiaMapLoadsWithItsPointsAndTheRobotStartsAtHome() throws IOException {
    try (SimWorld w = SimWorld.load(referenceMap("columbia.map"), SimOptions.defaults())) {
      WorldMap m = w.getMap();
      assertEquals(63_311, m.pointCount(), "every DATA point, whatever the header says");
      assertTrue(m.lines().size() > 400);
      assertEquals(10, m.pointRadius(), 1e-9, "half the 20 mm resolution");
      double ahead = w.castRay(-182, 176, 0, 30_000);
      assertTrue(ahead > 300 && ahead < 30_000, "from home a wall ahead: " + ahead);
      SimRobot r = w.addRobot("p3dx-sh");
      assertEquals(new ArPose(-182, 176, 0), r.getTruePose());
    }
  }

  @Test
  void triangleMapIsALineMapWithAHeadingAtHome() throws IOException {
    try (SimWorld w = SimWorld.load(referenceMap("triangle.map"), SimOptions.defaults())) {
      SimRobot r = w.addRobot("p3at-sh");
      assertEquals(new ArPose(5090, 3580, 54), r.getTruePose());
      assertEquals(0, w.getMap().pointCount());
      assertEquals(5090, w.castRay(5090, 2900, 180, 20_000), 1e-6, "the west wall is x = 0");
    }
  }

  @Test
  void bundledOfficeAndHallHostSeveralRobotsApart() {
    for (String name : List.of("office", "hall")) {
      try (SimWorld w = SimWorld.bundled(name, SimOptions.defaults())) {
        SimRobot a = w.addRobot("p3dx-sh");
        SimRobot b = w.addRobot("p3at-sh");
        SimRobot c = w.addRobot("p2dx");
        SimRobot d = w.addRobot("amigo");
        List<SimRobot> all = List.of(a, b, c, d);
        for (int i = 0; i < all.size(); i++) {
          for (int j = i + 1; j < all.size(); j++) {
            double gap = all.get(i).getTruePose().findDistanceTo(all.get(j).getTruePose());
            assertTrue(gap > 400, name + ": robots " + i + " and " + j + " overlap (" + gap + ")");
          }
        }
        w.advanceMillis(100);
        for (SimRobot r : all) {
          assertFalse(r.isStalled(), name + ": " + r + " starts touching something");
        }
      }
    }
  }

  @Test
  void forbiddenLinesAndAreasAreNotPhysical(@TempDir Path dir) throws IOException {
    Path map = dir.resolve("forbidden.map");
    Files.writeString(
        map,
        """
        2D-Map
        Cairn: ForbiddenLine 1000 -1000 0.0 "" ICON "" 1000 -1000 1000 1000
        Cairn: ForbiddenArea 0 0 0.0 "" ICON "" 1500 -500 2000 500
        Cairn: Dock -1500 800 90.0 "" ICON "dock"
        LINES
        3000 -1000 3000 1000
        DATA
        """);
    try (SimWorld w = SimWorld.load(map, SimOptions.defaults())) {
      assertEquals(3000, w.castRay(0, 0, 0, 10_000), 1e-6);
      SimRobot r = w.addRobot("p3dx-sh");
      // Away from the origin, so that starting at the Dock cannot pass for the origin fallback.
      assertEquals(new ArPose(-1500, 800, 90), r.getTruePose(), "no RobotHome: the Dock");
    }
  }

  @Test
  void malformedMapLineIsReportedWithFileAndLine(@TempDir Path dir) throws IOException {
    Path bad = dir.resolve("bad.map");
    Files.writeString(bad, "2D-Map\nLINES\n0 0 1000 0\n0 0 zero 5\nDATA\n");
    IOException e =
        assertThrows(IOException.class, () -> SimWorld.load(bad, SimOptions.defaults()));
    assertTrue(e.getMessage().contains("bad.map"), e.getMessage());
    assertTrue(e.getMessage().contains(":4"), "names line 4: " + e.getMessage());
  }

  @Test
  void modelsComeFromTheParameterFiles() {
    RobotModel dx = RobotModels.forSubtype("p3dx-sh");
    assertEquals(16, dx.getNumSonar());
    assertEquals(2200, dx.getTransVelTop(), 1e-9);
    assertEquals(500, dx.getRotVelTop(), 1e-9);
    assertEquals(425, dx.getWidth(), 1e-9);
    RobotModel at = RobotModels.forSubtype("P3AT-SH");
    assertEquals(1200, at.getTransVelTop(), 1e-9);
    assertEquals(0.0034, at.getDiffConvFactor(), 1e-12);
    RobotModel p2 = RobotModels.forSubtype("p2dx");
    assertEquals(0.84, p2.getDistConvFactor(), 1e-12);
    assertEquals(0.268, p2.getRangeConvFactor(), 1e-12);
    RobotModel amigo = RobotModels.forSubtype("amigo");
    assertEquals(8, amigo.getNumSonar());
    assertEquals(279, amigo.getWidth(), 1e-9);
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> RobotModels.forSubtype("r2d2"));
    assertTrue(e.getMessage().contains("p3dx-sh"), "lists what exists: " + e.getMessage());
  }

  @Test
  void sonarRangesUseTheModelsRangeConversion() {
    try (SimWorld w =
        SimWorld.ofLines(
            List.of(new org.jaria.geom.ArLineSegment(2000, -3000, 2000, 3000)),
            ArPose.ORIGIN,
            SimOptions.builder()
                .watchdogMillis(0)
                .sonar(SonarOptions.DEFAULTS.withNoise(0, 0))
                .build())) {
      SimRobot r = w.addRobot("p2dx");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      w.advanceMillis(1000);
      double mm = 2000 - r.getModel().getSonarX(3);
      boolean seen = false;
      for (var s : c.sips()) {
        for (int k = 0; k < s.getSonarCount(); k++) {
          if (s.getSonarNumber(k) == 3) {
            assertEquals(Math.round(Math.round(mm) / 0.268), s.getSonarRange(k));
            seen = true;
          }
        }
      }
      assertTrue(seen);
    }
  }
}
