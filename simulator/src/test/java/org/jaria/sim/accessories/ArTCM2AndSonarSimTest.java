package org.jaria.sim.accessories;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.compass.ArTCM2;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSonarAutoDisabler;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

/** ArTCM2 and ArSonarAutoDisabler against the simulator over ARCOS packets, on virtual time. */
class ArTCM2AndSonarSimTest {

  private static final Duration LIMIT = Duration.ofSeconds(20);

  @Test
  void theCompassReportsTheTrueHeading() {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot simRobot =
          world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(0, 0, 30)));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot)) {
        ArTCM2 compass = new ArTCM2(sim.robot());
        double[] seen = {-1};
        compass.addHeadingDataCallback(h -> seen[0] = h);
        assertTrue(compass.commandOnePacket());
        assertTrue(sim.runUntil(compass::haveData, LIMIT), "one TCM2pac");
        assertEquals(30, compass.getHeading(), 0.11);
        assertEquals(30, seen[0], 0.11);
        long one = compass.getPacketCount();
        sim.runMillis(1000);
        assertEquals(one, compass.getPacketCount(), "only one was asked for");

        assertTrue(compass.commandContinuousPackets());
        assertTrue(sim.runUntil(() -> compass.getPacketCount() > one + 5, LIMIT), "continuous");
        simRobot.setTruePose(new ArPose(0, 0, -90));
        assertTrue(sim.runUntil(() -> Math.abs(compass.getHeading() - 270) < 0.11, LIMIT));
        assertTrue(compass.getCalibrationH() > 0);

        assertTrue(compass.commandOff());
        sim.runMillis(500);
        long after = compass.getPacketCount();
        sim.runMillis(1000);
        assertEquals(after, compass.getPacketCount(), "off stops the packets");
      }
    }
  }

  @Test
  void sonarGoOffWhenParkedAndOnWhenDriving() {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot simRobot = world.addRobot(RobotOptions.of("p3dx-sh"));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot);
          ArSonarAutoDisabler disabler = new ArSonarAutoDisabler(sim.robot())) {
        ArRobot robot = sim.robot();
        assertTrue(sim.runUntil(robot::areSonarsEnabled, LIMIT), "on after connecting");
        assertTrue(sim.runUntil(() -> !robot.areSonarsEnabled(), LIMIT), "off while parked");
        robot.enableMotors();
        robot.setVel(300);
        assertTrue(sim.runUntil(robot::areSonarsEnabled, LIMIT), "on when driving");
        assertTrue(sim.runUntil(() -> robot.getVel() > 100, LIMIT), "under way");
        disabler.supress();
        assertTrue(sim.runUntil(() -> !robot.areSonarsEnabled(), LIMIT), "supressed: off");
        assertTrue(robot.getVel() > 100, "still driving");
        disabler.unsupress();
        assertTrue(sim.runUntil(robot::areSonarsEnabled, LIMIT));
        robot.stop();
        assertTrue(sim.runUntil(() -> !robot.areSonarsEnabled(), LIMIT), "off after stopping");
        assertFalse(disabler.isSupressed());
      }
    }
  }
}
