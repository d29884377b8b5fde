package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

/**
 * A robot taken out of a world leaves nothing behind: other robots' sonar, rays and bumpers stop
 * meeting it, pictures of the world no longer show it, its client is disconnected, its number is
 * not reused (so nothing that remembers a number can mix it up with a newer robot).
 */
class RobotRemovalTest {

  /** A 10 m long box; robot A at the west end looking east, B 1.5 m in front of it. */
  private static SimWorld corridor() {
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(-1000, -1500, 9000, -1500),
            new ArLineSegment(-1000, 1500, 9000, 1500),
            new ArLineSegment(-1000, -1500, -1000, 1500),
            new ArLineSegment(9000, -1500, 9000, 1500));
    return SimWorld.ofLines(walls, ArPose.ORIGIN, SimOptions.builder().watchdogMillis(0).build());
  }

  /**
   * The range the front sonar that look straight ahead report (p3dx: 3 and 4 at ±10°; 5000 for no
   * echo).
   */
  private static double frontRange(SimRobot r) {
    return Math.min(r.getSonarTruth(3).reportedRangeMm(), r.getSonarTruth(4).reportedRangeMm());
  }

  @Test
  void othersSonarAndRaysStopSeeingARemovedRobot() {
    try (SimWorld w = corridor()) {
      SimRobot a = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(0, 0, 0)));
      SimRobot b = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(1500, 0, 0)));
      new ArcosTestClient(w, a).open(); // the sonar fire while a client has the robot open
      w.advanceMillis(1000);
      double seenB = frontRange(a);
      assertTrue(seenB < 1500, "A's sonar sees B: " + seenB);
      assertTrue(w.castRay(300, 0, 0, 20_000, a) < 1500, "a ray from A meets B");

      assertTrue(w.removeRobot(b));
      assertFalse(w.removeRobot(b), "once only");
      assertTrue(b.isRemoved());
      assertEquals(List.of(a), w.getRobots());
      assertEquals(1, w.snapshot().robots().size(), "the picture no longer shows B");
      assertEquals(8700, w.castRay(300, 0, 0, 20_000, a), 1e-6, "the ray reaches the wall");
      w.advanceMillis(1000);
      assertTrue(frontRange(a) >= 4900, "A's sonar sees nothing near now: " + frontRange(a));

      // A drives through where B stood: nothing there to bump into.
      a.setTruePose(new ArPose(1500, 0, 0));
      w.advanceMillis(100);
      assertFalse(a.isStalled());
    }
  }

  @Test
  void aRemovedRobotsClientIsDisconnectedAndItsNumberIsNotReused() throws IOException {
    try (SimWorld w = corridor()) {
      SimRobot a = w.addRobot("p3dx-sh");
      SimRobot b = w.addRobot("p3dx-sh");
      ArDeviceConnection client = b.connectInMemory();
      w.advanceMillis(100);
      assertTrue(b.isClientConnected());

      w.removeRobot(b);
      assertFalse(b.isClientConnected(), "its session ended");
      byte[] buf = new byte[64];
      int n;
      do {
        n = client.read(buf, 0, buf.length, 0);
      } while (n > 0);
      assertEquals(-1, n, "the client's end sees the connection closed");
      IllegalStateException e = assertThrows(IllegalStateException.class, b::connectInMemory);
      assertTrue(e.getMessage().contains("removed"), e.getMessage());
      assertThrows(IndexOutOfBoundsException.class, () -> w.getRobot(1));

      SimRobot c = w.addRobot("p3dx-sh");
      assertEquals(2, c.getIndex(), "a new number, not B's");
      assertEquals("p3dx-sh_3", c.getName());
      assertEquals(c, w.getRobot(2));
      assertEquals(a, w.getRobot(0));
      w.advanceMillis(500); // the world keeps running with the newcomer
      assertEquals(2, w.snapshot().robots().size());
    }
  }
}
