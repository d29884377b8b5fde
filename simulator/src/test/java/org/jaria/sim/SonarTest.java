package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.StandardSip;
import org.junit.jupiter.api.Test;

/** Sonar ranges against known geometry, firing order and rate. */
class SonarTest {

  private static final SimOptions OPTS = SimOptions.builder().watchdogMillis(0).build();

  @Test
  void wallAheadGivesItsDistanceWithinNoise() {
    List<ArLineSegment> wall = List.of(new ArLineSegment(2000, -3000, 2000, 3000));
    try (SimWorld w = SimWorld.ofLines(wall, ArPose.ORIGIN, OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      w.advanceMillis(2000);
      // Sonar 3 faces +10°; its cone reaches the perpendicular to the wall.
      double expected = 2000 - r.getModel().getSonarX(3);
      SonarTruth t = r.getSonarTruth(3);
      assertTrue(t.fireCount() > 0);
      assertEquals(expected, t.trueRangeMm(), 1e-6);
      double sigma = OPTS.sonar().noiseMm() + OPTS.sonar().noiseFraction() * expected;
      assertEquals(expected, t.reportedRangeMm(), 4 * sigma);
      assertEquals(2000, t.hitX(), 1e-6);
      // The SIP carries readings of transducer 3 near that range.
      boolean seen = false;
      for (StandardSip s : c.sips()) {
        for (int k = 0; k < s.getSonarCount(); k++) {
          if (s.getSonarNumber(k) == 3) {
            assertEquals(expected, s.getSonarRange(k), 4 * sigma);
            seen = true;
          }
          if (s.getSonarNumber(k) >= 8) {
            assertEquals(5000, s.getSonarRange(k), "nothing behind the robot");
          }
        }
      }
      assertTrue(seen);
    }
  }

  @Test
  void nothingInRangeReads5000() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      new ArcosTestClient(w, r).open();
      w.advanceMillis(1000);
      for (SonarTruth t : r.getSonarTruth()) {
        assertTrue(t.fireCount() > 0);
        assertFalse(t.hasEcho());
        assertEquals(5000, t.reportedRangeMm());
      }
    }
  }

  @Test
  void grazingWallGivesNoEchoWithSpecularAndAnEchoWithout() {
    // Sonar 0 faces +90° (to the left); a wall parallel to its axis at x = 400.
    List<ArLineSegment> wall = List.of(new ArLineSegment(400, -5000, 400, 5000));
    for (boolean specular : new boolean[] {true, false}) {
      SimOptions o = OPTS.toBuilder().sonar(OPTS.sonar().withSpecular(specular)).build();
      try (SimWorld w = SimWorld.ofLines(wall, new ArPose(0, 0, 0), o)) {
        SimRobot r = w.addRobot("p3dx-sh");
        new ArcosTestClient(w, r).open();
        w.advanceMillis(1000);
        SonarTruth t = r.getSonarTruth(0);
        assertTrue(t.fireCount() > 0);
        if (specular) {
          assertFalse(t.hasEcho(), "a grazing wall reflects the ping away");
          assertEquals(5000, t.reportedRangeMm());
        } else {
          assertTrue(t.hasEcho());
          double x0 = r.getModel().getSonarX(0);
          assertEquals((400 - x0) / Math.cos(Math.toRadians(75)), t.trueRangeMm(), 1e-6);
        }
        // Sonar 3 faces the wall almost head on: an echo either way.
        assertTrue(r.getSonarTruth(3).hasEcho());
      }
    }
  }

  @Test
  void echoesNearerThanTheMinimumRangeReadAsNoEcho() {
    List<ArLineSegment> wall = List.of(new ArLineSegment(250, -3000, 250, 3000));
    SimOptions o = OPTS.toBuilder().sonar(OPTS.sonar().withNoise(0, 0)).build();
    try (SimWorld w = SimWorld.ofLines(wall, ArPose.ORIGIN, o)) {
      SimRobot r = w.addRobot("p3dx-sh");
      new ArcosTestClient(w, r).open();
      w.advanceMillis(1000);
      SonarTruth t = r.getSonarTruth(3);
      assertEquals(250 - r.getModel().getSonarX(3), t.trueRangeMm(), 1e-6);
      assertEquals(5000, t.reportedRangeMm(), "closer than 120 mm reads 5000, as on ARCOS");
    }
  }

  @Test
  void otherRobotsAreSeen() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot a = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(0, 0, 0)));
      SimRobot b = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(1500, 0, 0)));
      new ArcosTestClient(w, a).open();
      w.advanceMillis(1000);
      double expected = 1500 - b.getModel().getLengthRear() - a.getModel().getSonarX(3);
      assertEquals(expected, a.getSonarTruth(3).trueRangeMm(), 1e-6);
    }
  }

  private static long fired(SimRobot r, int from, int to) {
    long n = 0;
    for (int i = from; i < to; i++) {
      n += r.getSonarTruth(i).fireCount();
    }
    return n;
  }

  @Test
  void pollingSetsTheFiringOrderAndSonarCycleTheRate() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comData(
          ArCommands.POLLING, new byte[] {3, 1, 2}); // array 1 fires transducers 2, 0, 1 (0-based)
      w.step();
      c.clear();
      long front0 = fired(r, 0, 8);
      long rear0 = fired(r, 8, 16);
      w.advanceMillis(1200);
      assertEquals(30, fired(r, 0, 8) - front0, "one firing every 40 ms");
      assertEquals(30, fired(r, 8, 16) - rear0, "array 2 keeps its own sequence and rate");
      List<Integer> front = new ArrayList<>();
      for (StandardSip s : c.sips()) {
        for (int k = 0; k < s.getSonarCount(); k++) {
          if (s.getSonarNumber(k) < 8) {
            front.add(s.getSonarNumber(k));
          }
        }
      }
      int start = front.indexOf(2);
      assertTrue(start >= 0 && front.size() > 20);
      for (int i = start; i < front.size(); i++) {
        assertEquals(List.of(2, 0, 1).get((i - start) % 3), front.get(i), "firing order");
      }
      c.comInt(ArCommands.SONARCYCLE, 20); // 20 ms
      c.comInt(ArCommands.SONAR, 2 << 1); // bit 0 clear = off, bits 1..3 = array 2
      w.advanceMillis(100);
      front0 = fired(r, 0, 8);
      rear0 = fired(r, 8, 16);
      w.advanceMillis(1000);
      assertEquals(50, fired(r, 0, 8) - front0);
      assertEquals(0, fired(r, 8, 16) - rear0);
      assertEquals(0, c.lastSip().getFlags() & (1 << 2), "SIP flag of array 2 cleared");
      assertEquals(1 << 1, c.lastSip().getFlags() & (1 << 1));
    }
  }

  @Test
  void emptyPollingStringDisablesSonar() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comData(ArCommands.POLLING, new byte[0]);
      w.step();
      c.clear();
      w.advanceMillis(500);
      for (StandardSip s : c.sips()) {
        assertEquals(0, s.getSonarCount());
        assertEquals(0, s.getFlags() & 0x1E);
      }
    }
  }
}
