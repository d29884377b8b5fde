package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.sim.robot.RobotBody;
import org.junit.jupiter.api.Test;

/** Collisions stop the robot and set the stall bits and the bumper segment that touched. */
class CollisionTest {

  private static final SimOptions OPTS = SimOptions.builder().watchdogMillis(0).build();

  /** A wall across the x axis at x = 1000, and one at x = -1000. */
  private static SimWorld corridor() {
    return SimWorld.ofLines(
        List.of(
            new ArLineSegment(1000, -3000, 1000, 3000),
            new ArLineSegment(-1000, -3000, -1000, 3000)),
        ArPose.ORIGIN,
        OPTS);
  }

  @Test
  void drivingIntoAWallStallsAndPressesTheMiddleFrontBumper() {
    try (SimWorld w = corridor()) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 300);
      w.advanceMillis(6000);
      double front = r.getModel().getLengthFront();
      double x = r.getTruePose().x();
      assertTrue(
          x >= 1000 - front - RobotBody.BUMPER_TRAVEL && x <= 1000 - front,
          "stops against the wall, the bump ring pressed in: " + x);
      assertTrue(r.isStalled());
      assertEquals(0, r.getVel(), 1e-9);
      int bits = r.getStallAndBumpers();
      assertEquals(
          RobotBody.STALL_LEFT | RobotBody.STALL_RIGHT | 1 << (RobotBody.FRONT_BUMPER_SHIFT + 2),
          bits);
      StandardSip sip = c.lastSip();
      assertEquals(bits, sip.getStallAndBumpers(), "the SIP carries the same bits");
      assertEquals(1 << 2, r.getFrontBumpers());
      assertEquals(0, r.getRearBumpers());

      c.comInt(ArCommands.VEL, -300);
      w.advanceMillis(500);
      assertFalse(r.isStalled(), "backing away clears the stall");
      assertTrue(r.getTruePose().x() < x - 20, "backed away");
    }
  }

  @Test
  void reversingIntoAWallPressesTheRearBumper() {
    try (SimWorld w = corridor()) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, -300);
      w.advanceMillis(6000);
      double x = r.getTruePose().x();
      double rear = r.getModel().getLengthRear();
      assertTrue(x <= -1000 + rear + RobotBody.BUMPER_TRAVEL && x >= -1000 + rear, "x " + x);
      assertTrue(r.isStalled());
      assertEquals(1 << 2, r.getRearBumpers());
      assertEquals(0, r.getFrontBumpers());
    }
  }

  @Test
  void bumperSegmentFollowsTheContactAngle() {
    // A wall ahead and turned: the robot's front-left corner touches first.
    List<ArLineSegment> walls = List.of(new ArLineSegment(1200, -3000, 200, 3000));
    try (SimWorld w = SimWorld.ofLines(walls, ArPose.ORIGIN, OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 200);
      w.advanceMillis(8000);
      assertTrue(r.isStalled());
      int bumpers = r.getFrontBumpers();
      assertTrue(
          bumpers != 0 && (bumpers & ~0b11) == 0,
          "a left front segment (bumper 0 or 1): " + Integer.toBinaryString(bumpers));
    }
  }

  @Test
  void robotsBumpIntoEachOther() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot a = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(0, 0, 0)));
      SimRobot b = w.addRobot(RobotOptions.of("p3at-sh").withStartPose(new ArPose(1500, 0, 180)));
      ArcosTestClient c = new ArcosTestClient(w, a).open();
      c.comInt(ArCommands.VEL, 300);
      w.advanceMillis(8000);
      assertTrue(a.isStalled());
      double gap = b.getTruePose().x() - a.getTruePose().x();
      double touching = a.getModel().getLengthFront() + b.getModel().getLengthFront();
      assertTrue(gap >= touching && gap <= touching + RobotBody.BUMPER_TRAVEL, "gap " + gap);
      assertEquals(ArPose.ORIGIN.withX(1500).withTh(180), b.getTruePose(), "b was not pushed");
    }
  }

  @Test
  void bumpStallStopsTheDriveSoItDoesNotPushOn() {
    try (SimWorld w = corridor()) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.BUMPSTALL, 1); // front
      c.comInt(ArCommands.VEL, 300);
      w.advanceMillis(6000);
      assertFalse(r.isStalled(), "the drive stopped after the bump, nothing pushes any more");
      assertEquals(0, r.getVel(), 1e-9);
    }
  }

  @Test
  void robotPlacedInsideAnObstacleCanDriveOut() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      w.injectObstacle(new ArLineSegment(100, -1000, 100, 1000));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, -300);
      w.advanceMillis(2000);
      assertTrue(r.getTruePose().x() < -300, "moved away from the wall it stood in");
    }
  }
}
