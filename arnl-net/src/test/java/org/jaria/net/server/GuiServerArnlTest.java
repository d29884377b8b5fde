package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.geom.ArPose;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.Particles;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.server.modes.ArServerModes;
import org.junit.jupiter.api.Test;

/**
 * The thesis's guiServer with SonARNL on a simulated robot in lockstep: a client sees the
 * localization and its particles, sends a goal and watches the planned path until the robot is
 * there, relocalizes a kidnapped robot, and edits the localization's parameters.
 */
class GuiServerArnlTest {

  @Test
  void localizationStateAndParticles() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      LocalizationSnapshot s = LocalizationSnapshot.read(rig.call("getLocalizationSnapshot"));
      assertEquals("LOCALIZATION_SUCCESS", s.state());
      // ARNL's layout of the same state: ubyte state, ubyte2 score 0..100.
      org.jaria.net.data.LocState aria = org.jaria.net.data.LocState.read(rig.call("getLocState"));
      assertEquals("LOCALIZATION_SUCCESS", aria.stateName());
      assertEquals(s.score() * 100, aria.score(), 5);
      assertNotNull(s.pose());
      assertTrue(s.pose().findDistanceTo(rig.sim.sim().getTruePose()) < 200, "" + s.pose());
      assertFalse(s.lost());
      Particles p = Particles.read(rig.call("getLocPoints"));
      assertTrue(p.samples().hasHeadings());
      assertEquals(s.numSamples(), p.samples().size());
      for (ArPose q : p.samples().toPoses()) {
        assertTrue(q.findDistanceTo(s.pose()) < 2000, "particles gather round the pose: " + q);
      }
    }
  }

  @Test
  void aGoalIsPlannedFollowedAndReached() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      List<PathSnapshot> paths = new CopyOnWriteArrayList<>();
      AtomicReference<RobotUpdate> update = new AtomicReference<>();
      rig.client.addHandler("getPathSnapshot", p -> paths.add(PathSnapshot.read(p)));
      rig.client.addHandler("update", p -> update.set(RobotUpdate.read(p)));
      Futures.get(rig.client.request("getPathSnapshot", 20));
      Futures.get(rig.client.request("update", 20));
      rig.call("gotoGoal", "Room 101");
      assertEquals("Goto", ArServerModes.of(rig.gui.getServer()).getMode());
      Eventually.until(
          "the planned path",
          () -> paths.stream().anyMatch(p -> p.state().equals("MOVING_TO_GOAL")));
      PathSnapshot moving =
          paths.stream().filter(p -> p.state().equals("MOVING_TO_GOAL")).findFirst().orElseThrow();
      assertTrue(moving.path().size() >= 2, "a path of points");
      assertEquals(new ArPose(3000, 15000), moving.goal());
      // ARNL's layout of the path: byte2 count, byte4 x, y.
      org.jaria.net.data.PathPoints aria = org.jaria.net.data.PathPoints.read(rig.call("getPath"));
      assertTrue(aria.path().size() >= 2, "the path in getPath: " + aria.path());
      assertTrue(
          rig.runUntil(
              () ->
                  rig.nav.getPathPlanningTask().getState()
                      != org.jaria.arnl.ArPathPlanningTask.PathPlanningState.MOVING_TO_GOAL,
              120_000),
          "finished within 2 minutes of robot time");
      assertEquals(
          "REACHED_GOAL", rig.nav.getPathPlanningTask().getState().name(), "reached the goal");
      Eventually.until(
          "the client sees it arrive",
          () -> paths.get(paths.size() - 1).state().equals("REACHED_GOAL"));
      ArPose truth = rig.sim.sim().getTruePose();
      assertTrue(truth.findDistanceTo(new ArPose(3000, 15000)) < 500, "really there: " + truth);
      Eventually.until(
          "the update shows the robot there",
          () -> update.get().getPose().findDistanceTo(rig.robot.getPose()) < 1);
      assertTrue(update.get().status().contains("101"), update.get().status());
    }
  }

  @Test
  void stopCancelsTheGoal() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      rig.call("gotoPose", 27000, 9500);
      rig.run(3000);
      assertTrue(Math.abs(rig.robot.getVel()) > 50, "on its way");
      rig.call("stop");
      rig.run(2000);
      assertEquals("ABORTED_PATHPLAN", rig.nav.getPathPlanningTask().getState().name());
      assertTrue(Math.abs(rig.robot.getVel()) < 5, "stopped");
      assertEquals("Stop", ArServerModes.of(rig.gui.getServer()).getMode());
    }
  }

  @Test
  void aKidnappedRobotIsRelocalizedWhereTheOperatorSays() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      ArPose elsewhere = new ArPose(15000, 9500, 180);
      rig.sim.sim().setTruePose(elsewhere);
      rig.run(1000);
      assertTrue(rig.robot.getPose().findDistanceTo(elsewhere) > 5000, "it believes it is home");
      rig.call("localizeToPose", 15000, 9500, 180); // byte4 x, y, th; acknowledged when done
      rig.run(500);
      LocalizationSnapshot s = LocalizationSnapshot.read(rig.call("getLocalizationSnapshot"));
      assertTrue(s.pose().findDistanceTo(elsewhere) < 300, "localized there: " + s.pose());
    }
  }

  @Test
  void theLocalizationsParametersCanBeEdited() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      List<ConfigSection> sections = ConfigLayout.readAll(rig.call("getConfigBySections"));
      List<String> names = sections.stream().map(ConfigSection::name).toList();
      assertTrue(names.contains("Localization"), names.toString());
      assertEquals(
          "", rig.call("setConfig", "Section", "Localization", "NumSamples", "500").bufToStr());
      assertEquals(500, rig.nav.getLocalizationTask().getParams().getNumSamples());
      String refused =
          rig.call("setConfig", "Section", "Localization", "NumSamples", "5").bufToStr();
      assertTrue(refused.contains("NumSamples"), refused);
    }
  }
}
