package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.geom.ArPose;
import org.jaria.range.ArSensorReading;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** State reflection: what SIPs turn into. */
class ArRobotStateTest {

  private final LockstepRig rig = new LockstepRig();

  @BeforeEach
  void connect() {
    assertTrue(rig.connect());
    rig.run(200);
  }

  @Test
  void positionCountersWrapAt15Bits() {
    rig.sip.setPos(32700, 100, 0);
    rig.run(100);
    double x0 = rig.robot.getX();
    rig.sip.setPos(32760, 100, 0);
    rig.run(100);
    rig.sip.setPos(10, 100, 0); // wrapped past 32767
    rig.run(100);
    assertEquals(x0 + 60 + 18, rig.robot.getX(), 1e-9);
    rig.sip.setPos(32750, 100, 0); // and back again
    rig.run(100);
    assertEquals(x0 + 50, rig.robot.getX(), 1e-9);
  }

  @Test
  void headingUsesTheAngleConversionFactor() {
    double factor = rig.robot.getRobotParams().getAngleConvFactor();
    rig.sip.setPos(0, 0, 1024); // about a quarter turn at 2*pi/4096 per unit
    rig.run(100);
    assertEquals(Math.toDegrees(1024 * factor), rig.robot.getTh(), 1e-9);
    assertEquals(90, rig.robot.getTh(), 0.5);
    rig.sip.setPos(0, 0, -2048);
    rig.run(100);
    assertEquals(180, Math.abs(rig.robot.getTh()), 0.5);
  }

  @Test
  void turningThroughOneEightyCountsOnlyTheSmallTurn() {
    rig.sip.setPos(0, 0, 2040); // just under +180 degrees
    rig.run(100);
    double odo = rig.robot.getOdometerDegrees();
    rig.sip.setPos(0, 0, -2040); // just past it, on the other side
    rig.run(100);
    assertEquals(180, Math.abs(rig.robot.getTh()), 1.0);
    double turned = rig.robot.getOdometerDegrees() - odo;
    assertEquals(16 * 360.0 / 4096, turned, 0.05, "16 units, not a whole turn back");
  }

  @Test
  void drivingForwardAtAHeadingMovesAlongIt() {
    rig.sip.setPos(0, 0, 1024);
    rig.run(100);
    rig.sip.setPos(0, 500, 1024);
    rig.run(100);
    assertEquals(500, rig.robot.getY(), 1e-6);
    assertEquals(0, rig.robot.getX(), 1e-6);
  }

  @Test
  void velocitiesBatteryStallsAndFlagsAreConverted() {
    rig.sip.setWheelVels(200, 300).setBattery(128).setStallAndBumpers(0x0101 | 0x04);
    rig.sip.setFlags(0x21).setCompass(45).setMoving(true);
    rig.run(100);
    assertEquals(250, rig.robot.getVel(), 1e-9);
    assertEquals(Math.toDegrees(50 * 0.0056), rig.robot.getRotVel(), 1e-6);
    assertEquals(12.8, rig.robot.getBatteryVoltage(), 1e-9);
    assertTrue(rig.robot.isLeftMotorStalled());
    assertTrue(rig.robot.isRightMotorStalled());
    assertEquals(0x02, rig.robot.getRearBumpers());
    assertEquals(0, rig.robot.getFrontBumpers());
    assertTrue(rig.robot.areMotorsEnabled());
    assertTrue(rig.robot.isEStopPressed());
    assertFalse(rig.robot.areSonarsEnabled());
    assertEquals(90, rig.robot.getCompass());
    assertTrue(rig.robot.isMoving());
  }

  @Test
  void tailFieldsTakePrecedenceWhenPresent() {
    rig.sip.setWheelVels(0, 0).setPower(261, 3, 125, 0).setIo(0, 2, 200, 0x0F, 0xF0);
    rig.sip.setOptionalCount(9);
    rig.run(100);
    assertEquals(12.5, rig.robot.getRotVel(), 1e-9);
    assertEquals(26.1, rig.robot.getRealBatteryVoltage(), 1e-9);
    assertEquals(3, rig.robot.getChargeState());
    assertEquals(0x0F, rig.robot.getDigIn());
    assertEquals(0xF0, rig.robot.getDigOut());
    assertEquals(200, rig.robot.getAnalog());
  }

  @Test
  void sonarReadingsArePlacedWithTheSonarGeometry() {
    rig.sip.clearSonar().addSonar(3, 1000).addSonar(3, 1200).addSonar(12, 800);
    rig.run(100);
    // p3dx-sh sonar 3 sits at (166, 27) facing 10 degrees
    ArSensorReading r = rig.robot.getSonarReading(3);
    assertNotNull(r);
    assertEquals(1200, r.getRange(), "the later reading of one sonar in a SIP wins");
    assertEquals(1200, rig.robot.getSonarRange(3));
    assertEquals(166 + 1200 * Math.cos(Math.toRadians(10)), r.getX(), 1.0);
    assertEquals(27 + 1200 * Math.sin(Math.toRadians(10)), r.getY(), 1.0);
    assertEquals(-1, rig.robot.getSonarRange(5), "never reported");
    assertEquals(3, rig.robot.getClosestSonarNumber(-30, 30));
    assertEquals(800, rig.robot.getClosestSonarRange(150, -150));
  }

  @Test
  void moveToShiftsTheGlobalPoseButNotOdometry() {
    rig.sip.setPos(100, 0, 0);
    rig.run(100);
    ArPose before = rig.robot.getEncoderPose();
    rig.robot.moveTo(new ArPose(5000, 2000, 90));
    assertEquals(5000, rig.robot.getX(), 1e-6);
    assertEquals(90, rig.robot.getTh(), 1e-6);
    rig.sip.setPos(300, 0, 0); // 200 mm forward in odometry
    rig.run(100);
    assertEquals(5000, rig.robot.getX(), 1e-6);
    assertEquals(2200, rig.robot.getY(), 1e-6);
    assertEquals(before.x() + 200, rig.robot.getEncoderPose().x(), 1e-6);
  }
}
