package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

class RangeDevicesAndActionsTest {

  private static final ArMap OFFICE = ArMap.loadBundled("office");

  @Test
  void forbiddenRangeDeviceSeesForbiddenEdgesNearTheRobotOnly() {
    SimulatedRobot sim = SimSetup.start(OFFICE, 1);
    try {
      ArRobot robot = sim.robot();
      ArForbiddenRangeDevice forbidden = new ArForbiddenRangeDevice(OFFICE);
      robot.addRangeDevice(forbidden);
      assertTrue(forbidden.getPointCount() > 80);
      sim.runMillis(300);
      assertTrue(forbidden.getCurrentReadings().isEmpty(), "nothing forbidden near the home");
      // Next to the lab's forbidden area (12500..14500, 5500..8000), facing it.
      robot.moveTo(new ArPose(12000, 7000, 0));
      sim.runMillis(300);
      List<ArPose> seen = forbidden.getCurrentReadings();
      assertTrue(!seen.isEmpty());
      for (ArPose p : seen) {
        assertTrue(p.findDistanceTo(robot.getPose()) <= forbidden.getMaxRange() + 1);
      }
      double ahead = forbidden.currentReadingPolar(-10, 10);
      assertEquals(500, ahead, 60, "the area's west edge is 500 mm ahead");
      forbidden.disable();
      sim.runMillis(200);
      assertTrue(forbidden.getCurrentReadings().isEmpty());
    } finally {
      SimSetup.stop(sim);
    }
  }

  /** Drives ahead at 400 mm/s. */
  private static final class Forward extends ArAction {
    private final ArActionDesired d = new ArActionDesired();

    Forward() {
      super("forward");
    }

    @Override
    public ArActionDesired fire(ArActionDesired current) {
      d.reset();
      d.setVel(400);
      return d;
    }
  }

  @Test
  void slowDownWhenNotCertainLimitsSpeedUntilLocalized() {
    SimulatedRobot sim = SimSetup.start(OFFICE, 2);
    try {
      ArRobot robot = sim.robot();
      ArSonarLocalizationTask loc =
          ArSonarLocalizationTask.builder(robot, OFFICE)
              .mode(ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS)
              .build();
      ArActionSlowDownWhenNotCertain slow = new ArActionSlowDownWhenNotCertain(loc);
      slow.setSlowSpeeds(120, 20);
      robot.addAction(new Forward(), 50);
      robot.addAction(slow, 140);
      sim.runMillis(3000);
      assertEquals(120, robot.getVel(), 15, "not localized yet: slow");
      loc.forceUpdatePose(sim.sim().getTruePose());
      assertEquals(LockState.LOCKED, loc.getLockState());
      sim.runMillis(3000);
      assertTrue(robot.getVel() > 350, "localized: full speed " + robot.getVel());
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }
}
