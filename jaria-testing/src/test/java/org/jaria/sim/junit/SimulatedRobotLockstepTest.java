package org.jaria.sim.junit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

/**
 * ArRobot and the simulator in lockstep on virtual time, through the JUnit extension a user writes
 * such tests with.
 */
@SimulatedRobotTest(map = "hall", robot = "p3dx-sh", seed = 7)
class SimulatedRobotLockstepTest {

  @Test
  void moveDrivesOneMetreInTheWorld(ArRobot robot, SimulatedRobot sim, SimRobot truth) {
    ArPose start = truth.getTruePose();
    robot.enableMotors();
    robot.move(1000);
    assertTrue(sim.runUntil(() -> robot.isMoveDone() && !robot.isMoving(), Duration.ofSeconds(20)));
    double driven = truth.getTruePose().findDistanceTo(start);
    assertEquals(1000, driven, 30, "the simulated robot drove what the client asked");
    assertEquals(1000, robot.getPose().findDistanceTo(ArPose.ORIGIN), 30, "odometry agrees");
  }

  @Test
  void aMinuteOfRobotTimeIsFastAndCyclesFollowSips(ArRobot robot, SimulatedRobot sim) {
    long c0 = robot.getCounter();
    sim.run(Duration.ofSeconds(60));
    long cycles = robot.getCounter() - c0;
    assertTrue(cycles >= 590 && cycles <= 610, "one cycle per SIP: " + cycles);
    assertTrue(robot.isConnected());
  }

  @Test
  void headingCommandsTurnTheShortWay(ArRobot robot, SimulatedRobot sim, SimRobot truth) {
    robot.enableMotors();
    robot.setHeading(170);
    assertTrue(sim.runUntil(robot::isHeadingDone, Duration.ofSeconds(10)));
    sim.runMillis(1000);
    robot.setHeading(-170);
    sim.runMillis(300);
    assertTrue(truth.getRotVel() > 0, "170 to -170 goes counter-clockwise through 180");
    assertTrue(sim.runUntil(robot::isHeadingDone, Duration.ofSeconds(10)));
  }

  @Test
  void sonarReadingsMatchTheSimulatorsTruth(ArRobot robot, SimulatedRobot sim, SimWorld world) {
    ArSonarDevice sonar = new ArSonarDevice();
    robot.addRangeDevice(sonar);
    sim.runMillis(2000);
    int seen = 0;
    for (int i = 0; i < robot.getNumSonar(); i++) {
      int client = robot.getSonarRange(i);
      double truthRange = sim.sim().getSonarTruth(i).reportedRangeMm();
      if (client > 0 && client < 5000) {
        assertEquals(truthRange, client, 100, "sonar " + i);
        seen++;
      }
    }
    assertTrue(seen > 0, "some sonar sees a wall or pillar in the hall");
    assertFalse(sonar.getCurrentReadings().isEmpty());
    assertTrue(world.getStepCount() > 0);
  }

  @Test
  void droppedConnectionIsNoticed() {
    try (SimulatedRobot s = SimulatedRobot.start("office", "p3at-sh", 3)) {
      s.runMillis(500);
      assertEquals("p3at-sh", s.robot().getRobotSubType());
      s.sim().dropConnection();
      s.runMillis(500);
      assertFalse(s.robot().isConnected());
    }
  }

  @Test
  void sameSeedSameRun() {
    ArPose[] ends = new ArPose[2];
    for (int k = 0; k < 2; k++) {
      try (SimulatedRobot s = SimulatedRobot.start("office", "p3dx-sh", 42)) {
        s.robot().enableMotors();
        s.robot().setVel(300);
        s.robot().setRotVel(10);
        s.runMillis(8000);
        ends[k] = s.sim().getTruePose();
      }
    }
    assertEquals(ends[0], ends[1]);
  }
}
