package org.jaria.range;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class ArSonarDeviceTest {

  private final LockstepRig rig = new LockstepRig();
  private final ArSonarDevice sonar = new ArSonarDevice();

  @BeforeEach
  void connect() {
    rig.robot.addRangeDevice(sonar);
    assertTrue(rig.connect());
    rig.run(200);
  }

  @Test
  void frontReadingIsFoundByPolarAndBoxQueries() {
    // sonar 3 (166, 27) faces 10 degrees, sonar 4 (166, -27) faces -10 degrees
    rig.sip.clearSonar().addSonar(3, 834).addSonar(4, 834);
    rig.run(100);
    double d = sonar.currentReadingPolar(-20, 20);
    assertEquals(Math.hypot(166 + 834 * Math.cos(0.1745), 27 + 834 * Math.sin(0.1745)), d, 1);
    assertTrue(rig.robot.checkRangeDevicesCurrentPolar(-20, 20) < 1100);
    assertEquals(5000, sonar.currentReadingPolar(60, 120), "nothing on the left");
    double box = rig.robot.checkRangeDevicesCurrentBox(0, -300, 1500, 300);
    assertTrue(box > 900 && box < 1100, "box " + box);
    assertEquals(5000, sonar.currentReadingBox(0, 400, 1500, 800));
  }

  @Test
  void noEchoIsNotAnObstacle() {
    rig.sip.clearSonar().addSonar(3, 5000).addSonar(4, 5000);
    rig.run(100);
    assertEquals(0, sonar.getCurrentReadings().size());
    assertEquals(0, sonar.getCumulativeReadings().size());
  }

  @Test
  void cumulativeKeepsObstaclesTheRobotDroveBesideAndForgetsOnesSeenThrough() {
    rig.sip.clearSonar().addSonar(0, 500); // sonar 0 looks left
    rig.run(100);
    assertEquals(1, sonar.getCumulativeReadings().size());
    rig.sip.clearSonar().addSonar(0, 2000); // now the left is clear beyond the old point
    rig.run(100);
    assertEquals(1, sonar.getCumulativeReadings().size(), "the 500 mm point was seen through");
    assertTrue(sonar.cumulativeReadingPolar(80, 100) > 1500);
    rig.sip.clearSonar();
    rig.run(100);
    assertEquals(1, sonar.getCurrentReadings().size(), "current keeps each sonar's latest");
  }

  @Test
  void readingsMoveWithTheRobotWhenThePoseIsCorrected() {
    rig.sip.clearSonar().addSonar(3, 834);
    rig.run(100);
    double before = sonar.currentReadingPolar(-20, 20);
    rig.robot.moveTo(new org.jaria.geom.ArPose(10_000, 5_000, 45));
    assertEquals(before, sonar.currentReadingPolar(-20, 20), 1e-6);
  }
}
