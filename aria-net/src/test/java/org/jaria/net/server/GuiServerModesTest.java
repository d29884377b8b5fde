package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.net.client.ArClientException;
import org.jaria.net.protocol.NetError;
import org.jaria.net.server.modes.ArServerModes;
import org.junit.jupiter.api.Test;

/**
 * The modes as a client drives them, on a simulated robot in lockstep without SonARNL: stop,
 * teleoperation with its deadman timeout, wander, goto a pose or a goal in a straight line, and
 * relocalizing by declaring the pose.
 */
class GuiServerModesTest {

  private static String mode(GuiRig rig) {
    return ArServerModes.of(rig.gui.getServer()).getMode();
  }

  private static String status(GuiRig rig) {
    return ArServerModes.of(rig.gui.getServer()).getStatus();
  }

  @Test
  void teleoperationDrivesAndTheDeadmanStopsIt() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      ArPose start = rig.sim.sim().getTruePose();
      for (int i = 0; i < 20; i++) {
        rig.call("ratioDrive", 50.0, 0.0, 100.0);
        rig.run(100);
      }
      assertEquals("Drive", mode(rig));
      assertEquals("Driving", status(rig));
      double driven = rig.sim.sim().getTruePose().findDistanceTo(start);
      assertTrue(driven > 300, "drove forward: " + driven + " mm");
      // No more commands: 2 s later (robot time) the ratios drop to zero and the robot brakes.
      rig.run(2100);
      assertEquals("Stopped: no drive command for 2.0 s", status(rig));
      assertTrue(
          rig.runUntil(() -> Math.abs(rig.robot.getVel()) < 5, 5000),
          "stopped: " + rig.robot.getVel());
      assertTrue(rig.call("getSafeDrive").bufToBool());
    }
  }

  @Test
  void stopStopsWhateverTheRobotDoes() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      rig.call("wander");
      rig.run(4000);
      assertEquals("Wander", mode(rig));
      assertTrue(Math.abs(rig.robot.getVel()) > 50, "wandering: " + rig.robot.getVel());
      rig.call("stop");
      assertTrue(rig.runUntil(() -> "Stopped".equals(status(rig)), 3000), status(rig));
      assertEquals("Stop", mode(rig));
      ArPose stopped = rig.sim.sim().getTruePose();
      rig.run(2000);
      assertTrue(stopped.findDistanceTo(rig.sim.sim().getTruePose()) < 1, "and it stays");
    }
  }

  @Test
  void wanderMovesWithoutHittingAnything() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      ArPose start = rig.sim.sim().getTruePose();
      rig.call("wander");
      rig.run(15_000);
      assertEquals("Wandering", status(rig));
      assertTrue(start.findDistanceTo(rig.sim.sim().getTruePose()) > 1000, "it went somewhere");
      assertTrue(!rig.sim.sim().isStalled());
    }
  }

  @Test
  void gotoPoseAndGoalInAStraightLine() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      rig.call("gotoPose", 4000, 9500); // ArNetworking's layout: byte4 x, byte4 y
      ArClientException nan =
          assertThrows(
              ArClientException.class, () -> rig.call("ratioDrive", Double.NaN, 0.0, 50.0));
      assertEquals(NetError.BAD_ARGUMENTS, nan.getCode());
      ArClientException off =
          assertThrows(ArClientException.class, () -> rig.call("gotoPose", 900_000, 9500));
      assertTrue(off.getMessage().contains("outside the map"), off.getMessage());
      assertEquals("Goto", mode(rig));
      assertEquals("Going to pose (4000, 9500)", status(rig));
      assertTrue(
          rig.runUntil(() -> status(rig).startsWith("Arrived"), 30_000), "arrived: " + status(rig));
      assertTrue(rig.sim.sim().getTruePose().findDistanceTo(new ArPose(4000, 9500)) < 300);
      List<String> goals = GuiRig.stringsToEnd(rig.call("getGoals"));
      assertTrue(goals.contains("Corridor West"), goals.toString());
      rig.call("gotoGoal", "corridor west");
      assertEquals("Going to goal corridor west", status(rig));
      ArClientException e =
          assertThrows(ArClientException.class, () -> rig.call("gotoGoal", "Mars"));
      assertEquals(NetError.BAD_ARGUMENTS, e.getCode());
      assertEquals("no goal called 'Mars' on the map; see getGoals", e.getMessage());
    }
  }

  @Test
  void relocalizingWithoutALocalizerDeclaresThePose() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      rig.call("localizeToPose", 2000, 9000, 90);
      ArClientException off =
          assertThrows(
              ArClientException.class, () -> rig.call("localizeToPose", 2000, -900_000, 0));
      assertEquals(NetError.BAD_ARGUMENTS, off.getCode());
      rig.run(200);
      ArPose p = rig.robot.getPose();
      assertEquals(2000, p.x(), 1);
      assertEquals(9000, p.y(), 1);
      assertEquals(90, p.th(), 0.5);
    }
  }
}
