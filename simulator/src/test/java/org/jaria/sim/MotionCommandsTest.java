package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Each motion command's effect, through the protocol, on virtual time. */
class MotionCommandsTest {

  private SimWorld world;
  private SimRobot robot;
  private ArcosTestClient client;

  @BeforeEach
  void setUp() {
    world = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build());
    robot = world.addRobot("p3dx-sh");
    client = new ArcosTestClient(world, robot).open();
  }

  @AfterEach
  void tearDown() {
    world.close();
  }

  @Test
  void velocityFollowsTrapezoidWithSetAccelerations() {
    client.comInt(ArCommands.SETA, 500); // +500: acceleration
    client.comInt(ArCommands.SETA, -250); // -250: deceleration
    client.comInt(ArCommands.VEL, 1000);
    world.advanceMillis(500);
    assertEquals(250, robot.getVel(), 1e-6);
    world.advanceMillis(500);
    assertEquals(500, robot.getVel(), 1e-6);
    world.advanceMillis(1000);
    assertEquals(1000, robot.getVel(), 1e-6);
    world.advanceMillis(1000);
    assertEquals(1000, robot.getVel(), 1e-6);
    client.comInt(ArCommands.VEL, 0);
    world.advanceMillis(2000);
    assertEquals(500, robot.getVel(), 1e-6);
    world.advanceMillis(2000);
    assertEquals(0, robot.getVel(), 1e-6);
    world.advanceMillis(200);
    StandardSip sip = client.lastSip();
    assertEquals(0, sip.getLeftVel());
    assertEquals(PacketIds.SIP_STOPPED, sip.getId());
  }

  @Test
  void sipReportsWheelVelocitiesWhileMoving() {
    client.comInt(ArCommands.VEL, 400);
    world.advanceMillis(3000);
    StandardSip sip = client.lastSip();
    assertEquals(400, sip.getLeftVel());
    assertEquals(400, sip.getRightVel());
    assertEquals(PacketIds.SIP_MOVING, sip.getId());
    assertEquals(1, sip.getFlags() & 1, "motors enabled");
  }

  @Test
  void moveTravelsTheDistanceAccurately() {
    ArPose start = robot.getTruePose();
    client.comInt(ArCommands.SETV, 400);
    client.comInt(ArCommands.MOVE, 1000);
    world.advanceMillis(8000);
    ArPose end = robot.getTruePose();
    assertEquals(1000, end.findDistanceTo(start), 0.5);
    assertEquals(0, robot.getVel(), 1e-9);
    client.comInt(ArCommands.MOVE, -500);
    world.advanceMillis(6000);
    assertEquals(500, robot.getTruePose().findDistanceTo(start), 0.5);
  }

  @Test
  void moveIsClampedToFiveMetres() {
    ArPose start = robot.getTruePose();
    client.comInt(ArCommands.SETV, 1500);
    client.comInt(ArCommands.MOVE, 9000);
    world.advanceMillis(15_000);
    assertEquals(5000, robot.getTruePose().findDistanceTo(start), 0.5);
  }

  @Test
  void headTakesTheShortestWayAcrossPlusMinus180() {
    client.comInt(ArCommands.SETRV, 100);
    client.comInt(ArCommands.HEAD, 170);
    world.advanceMillis(5000);
    assertEquals(170, robot.getTruePose().th(), 0.05);
    client.comInt(ArCommands.HEAD, -170);
    world.advanceMillis(200);
    assertTrue(robot.getRotVel() > 0, "turns counter-clockwise through 180, not 340° back");
    world.advanceMillis(3000);
    assertEquals(0, ArMath.subAngle(robot.getTruePose().th(), -170), 0.05);
    client.comInt(ArCommands.DHEAD, 270); // 270 = -90 the short way
    world.advanceMillis(200);
    assertTrue(robot.getRotVel() < 0, "DHEAD 270 turns clockwise");
    world.advanceMillis(4000);
    assertEquals(0, ArMath.subAngle(robot.getTruePose().th(), 100), 0.05);
    double units = client.lastSip().getControl() * robot.getModel().getAngleConvFactor();
    assertEquals(
        100, Math.toDegrees(units), 0.2, "CONTROL carries the setpoint in angle units, as THPOS");
  }

  @Test
  void dcheadIsRelativeToTheLastSetpoint() {
    client.comInt(ArCommands.SETRV, 100);
    client.comInt(ArCommands.HEAD, 30);
    client.comInt(ArCommands.DCHEAD, 30); // 30 beyond the setpoint 30, whatever the heading now
    world.advanceMillis(4000);
    assertEquals(60, robot.getTruePose().th(), 0.05);
  }

  @Test
  void vel2IsDecomposedIntoTranslationAndRotation() {
    client.com2Bytes(ArCommands.VEL2, 10, 20); // left 200 mm/s, right 400 mm/s
    world.advanceMillis(3000);
    double track = 2 / robot.getModel().getDiffConvFactor();
    assertEquals(300, robot.getVel(), 1e-6);
    assertEquals(Math.toDegrees(200 / track), robot.getRotVel(), 1e-6);
    client.com2Bytes(ArCommands.VEL2, -10, -10); // both back at 200 mm/s
    world.advanceMillis(4000);
    assertEquals(-200, robot.getVel(), 1e-6);
    assertEquals(0, robot.getRotVel(), 1e-6);
  }

  @Test
  void eStopUsesTheMaximumDecelerationAndIgnoresMotionUntilStopped() {
    client.comInt(ArCommands.VEL, 1000);
    world.advanceMillis(5000);
    assertEquals(1000, robot.getVel(), 1e-6);
    client.com(ArCommands.E_STOP);
    world.advanceMillis(250);
    double top = robot.getModel().getTransAccTop();
    assertEquals(1000 - top * 0.25, robot.getVel(), 1e-6);
    client.comInt(ArCommands.VEL, 600); // ignored while e-stopping
    world.advanceMillis(250);
    assertEquals(0, robot.getVel(), 1e-6);
    world.advanceMillis(1000);
    assertEquals(0, robot.getVel(), 1e-6, "stays stopped until a new motion command");
    client.comInt(ArCommands.VEL, 600);
    world.advanceMillis(3000);
    assertEquals(600, robot.getVel(), 1e-6);
  }

  @Test
  void setvAndSetrvAreClampedByTheFirmwareTops() {
    client.comInt(ArCommands.SETV, 5000);
    client.comInt(ArCommands.SETRV, 1000);
    client.comInt(ArCommands.SETA, 30_000);
    client.comInt(ArCommands.SETRA, 30_000);
    client.comInt(ArCommands.VEL, 3000);
    client.comInt(ArCommands.RVEL, 900);
    world.advanceMillis(4000);
    assertEquals(robot.getModel().getTransVelTop(), robot.getVel(), 1e-6);
    assertEquals(robot.getModel().getRotVelTop(), robot.getRotVel(), 1e-6);
    client.comInt(ArCommands.CONFIG, 1);
    ArConfigPacket c = ArConfigPacket.decode(client.awaitId(PacketIds.CONFIG));
    assertEquals(2200, c.getTransVelMax());
    assertEquals(500, c.getRotVelMax());
    assertEquals(2000, c.getInt(ArConfigPacket.Field.TRANS_ACCEL));
  }

  @Test
  void velocityIsLimitedBySetv() {
    client.comInt(ArCommands.SETV, 300);
    client.comInt(ArCommands.VEL, 800);
    world.advanceMillis(3000);
    assertEquals(300, robot.getVel(), 1e-6);
    client.comInt(ArCommands.SETRVDIR, -40); // clockwise maximum only
    client.comInt(ArCommands.RVEL, -90);
    world.advanceMillis(3000);
    assertEquals(-40, robot.getRotVel(), 1e-6);
  }

  @Test
  void stopDeceleratesNormally() {
    client.comInt(ArCommands.VEL, 600);
    client.comInt(ArCommands.RVEL, 30);
    world.advanceMillis(3000);
    client.com(ArCommands.STOP);
    world.advanceMillis(1000);
    assertEquals(300, robot.getVel(), 1e-6);
    world.advanceMillis(2000);
    assertEquals(0, robot.getVel(), 1e-6);
    assertEquals(0, robot.getRotVel(), 1e-6);
    assertTrue(robot.areMotorsEnabled(), "STOP keeps the motors enabled");
  }

  @Test
  void motorsAreDisabledUntilEnable() {
    SimWorld w = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build());
    try {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r);
      for (int s = 0; s < 3; s++) {
        c.com(s);
        c.awaitId(s);
      }
      c.comInt(ArCommands.OPEN, 1);
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(1000);
      assertEquals(0, r.getVel(), 1e-9);
      assertEquals(0, c.lastSip().getFlags() & 1);
      c.comInt(ArCommands.ENABLE, 1);
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(3000);
      assertEquals(500, r.getVel(), 1e-9);
    } finally {
      w.close();
    }
  }
}
