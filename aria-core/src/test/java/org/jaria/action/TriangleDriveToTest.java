package org.jaria.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.jaria.action.ArActionTriangleDriveTo.State;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.range.LaserScan;
import org.junit.jupiter.api.Test;

/** The line finder, the triangle finder, and driving up to a docking target. */
class TriangleDriveToTest {

  private final TriangleWorld dock =
      new TriangleWorld().triangle(2000, 0, 180, 254, 135).wall(2600, -2000, 2600, 2000);

  @Test
  void scanPointsAreInGlobalCoordinatesAndNoEchoIsSkipped() {
    LaserScan s =
        new LaserScan(
            new ArPose(100, 200, 90), new double[] {0, 90, 10}, new double[] {1000, 500, 0}, 8000);
    assertEquals(3, s.size());
    assertEquals(2, s.getNumPoints());
    assertEquals(100, s.getX(0), 1e-6);
    assertEquals(1200, s.getY(0), 1e-6);
    assertEquals(-400, s.getX(1), 1e-6);
    assertThrows(
        IllegalArgumentException.class,
        () -> new LaserScan(ArPose.ORIGIN, new double[1], new double[2], 8000));
  }

  @Test
  void lineFinderFindsTheTwoSidesInSweepOrder() {
    List<ArLineFinderSegment> lines = new ArLineFinder().getLines(dock.scan(ArPose.ORIGIN));
    ArLineFinderSegment right = null;
    ArLineFinderSegment left = null;
    for (int i = 0; i + 1 < lines.size(); i++) {
      if (Math.abs(lines.get(i).getLength() - 254) < 30
          && Math.abs(lines.get(i + 1).getLength() - 254) < 30) {
        right = lines.get(i);
        left = lines.get(i + 1);
      }
    }
    assertNotNull(right, "lines: " + lines);
    assertTrue(right.y1() < left.y2(), "the right side is scanned first");
    assertEquals(112.5, right.getLineAngle(), 2);
    assertEquals(67.5, left.getLineAngle(), 2);
    ArPose corner = right.intersection(left);
    assertEquals(2000, corner.x(), 5);
    assertEquals(0, corner.y(), 5);
  }

  @Test
  void triangleFinderFindsTheVertexFacingTheRobot() {
    List<ArLineFinderSegment> lines = new ArLineFinder().getLines(dock.scan(ArPose.ORIGIN));
    TriangleFinder.Vertex v = new TriangleFinder().find(lines, ArPose.ORIGIN, true, false, null, 0);
    assertNotNull(v);
    assertEquals(2000, v.pose().x(), 5);
    assertEquals(0, v.pose().y(), 5);
    assertEquals(0, ArMath.subAngle(180, v.pose().th()), 2);
  }

  @Test
  void triangleFinderIgnoresOtherShapes() {
    TriangleWorld square = new TriangleWorld().triangle(2000, 0, 180, 254, 90);
    List<ArLineFinderSegment> lines = new ArLineFinder().getLines(square.scan(ArPose.ORIGIN));
    assertNull(new TriangleFinder().find(lines, ArPose.ORIGIN, true, false, null, 0));
    TriangleWorld big = new TriangleWorld().triangle(2000, 0, 180, 600, 135);
    lines = new ArLineFinder().getLines(big.scan(ArPose.ORIGIN));
    assertNull(new TriangleFinder().find(lines, ArPose.ORIGIN, true, false, null, 0));
  }

  @Test
  void garbageScansNeverBreakTheFinders() {
    Random rnd = new Random(42);
    ArLineFinder lf = new ArLineFinder();
    TriangleFinder tf = new TriangleFinder();
    for (int k = 0; k < 200; k++) {
      int n = rnd.nextInt(400);
      double[] ranges = new double[n];
      for (int i = 0; i < n; i++) {
        ranges[i] = rnd.nextInt(5) == 0 ? Double.NaN : rnd.nextDouble() * 9000 - 500;
      }
      LaserScan s =
          LaserScan.evenlySpaced(ArPose.ORIGIN, -90, 180.0 / Math.max(1, n), ranges, 8000);
      List<ArLineFinderSegment> lines = lf.getLines(s);
      for (ArLineFinderSegment l : lines) {
        assertTrue(l.numPoints() >= 3 && l.getLength() >= 75);
      }
      tf.find(lines, ArPose.ORIGIN, rnd.nextBoolean(), rnd.nextBoolean(), ArPose.ORIGIN, 0);
    }
  }

  @Test
  void drivesToTheApproachPointThenTheFinalPoint() {
    ActionRig ar = new ActionRig();
    ArActionTriangleDriveTo t =
        ar.attach(new ArActionTriangleDriveTo("dock", () -> dock.scan(ar.robot().getPose())));
    assertNull(ActionRig.fire(t), "does nothing until activated");
    t.activate();
    ArActionDesired d = ActionRig.fire(t);
    assertEquals(State.STATE_GOTO_APPROACH, t.getState());
    assertEquals(2000, t.getVertex().x(), 5);
    assertEquals(0, d.getHeading(), 1);
    assertEquals(200, d.getVel(), 1e-9);

    ar.rig.sip.setPos(1000, 0, 0);
    ar.run(100);
    d = ActionRig.fire(t);
    assertEquals(State.STATE_GOTO_FINAL, t.getState(), "aligned at the approach point");
    assertEquals(200, d.getVel(), 1e-9);

    ar.rig.sip.setPos(1580, 0, 0);
    ar.run(100);
    d = ActionRig.fire(t);
    assertEquals(State.STATE_SUCCEEDED, t.getState());
    assertEquals(0, d.getVel(), 1e-9);
    t.deactivate();
    assertNull(ActionRig.fire(t));
  }

  @Test
  void failsWithoutALaserOrWhenTheTargetStaysUnseen() {
    ActionRig ar = new ActionRig();
    ArActionTriangleDriveTo none = ar.attach(new ArActionTriangleDriveTo());
    none.activate();
    ArActionDesired d = ActionRig.fire(none);
    assertEquals(State.STATE_FAILED, none.getState());
    assertEquals(0, d.getVel(), 1e-9);

    TriangleWorld empty = new TriangleWorld().wall(3000, -3000, 3000, 3000);
    ArActionTriangleDriveTo t =
        ar.attach(new ArActionTriangleDriveTo("t", () -> empty.scan(ar.robot().getPose())));
    t.activate();
    ActionRig.fire(t);
    assertEquals(State.STATE_ACQUIRE, t.getState());
    ar.run(4100);
    ActionRig.fire(t);
    assertEquals(State.STATE_FAILED, t.getState());

    t.setAcquire(true);
    t.activate();
    ar.run(4100);
    d = ActionRig.fire(t);
    assertEquals(State.STATE_SEARCHING, t.getState());
    assertEquals(30, d.getRotVel(), 1e-9, "turning to look for it");
  }
}
