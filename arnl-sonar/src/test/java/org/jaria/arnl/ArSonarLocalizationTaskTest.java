package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.arnl.ArBaseLocalizationTask.UpdateMode;
import org.jaria.arnl.mcl.PoseEstimate;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("slow")
class ArSonarLocalizationTaskTest {

  private static final ArMap OFFICE = ArMap.loadBundled("office");

  private static ArSonarLocalizationTask sync(ArRobot robot, ArMap map, long seed) {
    return ArSonarLocalizationTask.builder(robot, map)
        .mode(UpdateMode.SYNCHRONOUS)
        .seed(seed)
        .build();
  }

  @Test
  void tracksALongRouteThroughTheOfficeWithin150mmAnd5Degrees() {
    SimulatedRobot sim = SimSetup.start(OFFICE, 1);
    try {
      ArRobot robot = sim.robot();
      ArSonarLocalizationTask loc = sync(robot, OFFICE, 1);
      sim.runMillis(1000);
      assertTrue(loc.localizeRobotAtHomeBlocking());
      // Corridor, into two rooms through their doors, the meeting room, and back: about 77 m.
      TrueRoute route =
          new TrueRoute(
              sim.sim(),
              List.of(
                  new ArPose(9000, 9500),
                  new ArPose(9000, 12000),
                  new ArPose(9000, 15000),
                  new ArPose(9000, 12000),
                  new ArPose(9000, 9500),
                  new ArPose(15000, 9500),
                  new ArPose(15000, 15000),
                  new ArPose(15000, 9500),
                  new ArPose(26000, 9500),
                  new ArPose(26250, 7000),
                  new ArPose(26250, 6000),
                  new ArPose(26250, 9500),
                  new ArPose(1500, 9500)),
              500);
      robot.addAction(route, 50);
      double[] worst = new double[2];
      // Compare at each cycle, when the robot's pose and the simulator's truth refer to the same
      // instant (the SIP just received).
      robot.addUserTask(
          "measure",
          10,
          () -> {
            ArPose t = sim.sim().getTruePose();
            ArPose e = robot.getPose();
            worst[0] = Math.max(worst[0], t.findDistanceTo(e));
            worst[1] = Math.max(worst[1], Math.abs(ArMath.subAngle(t.th(), e.th())));
          });
      assertTrue(sim.runUntil(route::done, Duration.ofMinutes(5)), "route finished");
      assertTrue(robot.getOdometerDistance() > 70_000, "drove " + robot.getOdometerDistance());
      assertTrue(worst[0] < 150, "position error reached " + worst[0] + " mm");
      assertTrue(worst[1] < 5, "heading error reached " + worst[1] + " deg");
      assertTrue(loc.getUpdateCount() > 300, "updates " + loc.getUpdateCount());
      assertEquals(LockState.LOCKED, loc.getLockState());
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }

  @Test
  void localizesAtHomeAndReportsItsState() {
    SimulatedRobot sim = SimSetup.start(OFFICE, 2);
    try {
      ArSonarLocalizationTask loc = sync(sim.robot(), OFFICE, 2);
      List<LockState> changes = new ArrayList<>();
      loc.addStateChangeCB(() -> changes.add(loc.getLockState()));
      assertEquals(LocalizationState.NOT_INITIALIZED, loc.getState());
      // Odometry starts at 0,0,0 while the robot stands at the map's home (1500, 9500).
      assertTrue(sim.robot().getPose().findDistanceTo(ArPose.ORIGIN) < 1);
      sim.runMillis(1000);
      assertTrue(loc.localizeRobotAtHomeBlocking());
      assertTrue(sim.robot().getPose().findDistanceTo(new ArPose(1500, 9500)) < 100);
      assertTrue(loc.getRobotHome().findDistanceTo(new ArPose(1500, 9500)) < 100);
      assertTrue(loc.getLocalizationScore() > 0.8, "score " + loc.getLocalizationScore());
      assertEquals(2000, loc.getCurrentNumSamples());
      assertEquals(LocalizationState.LOCALIZATION_SUCCESS, loc.getState());
      assertEquals(List.of(LockState.LOCKED), changes);
      assertEquals(2000, loc.getCurrentSamplePoses().size());
      PoseEstimate e = loc.getEstimate();
      assertTrue(e.stdX() < 200 && e.stdY() < 200, e.toString());

      loc.forceUpdatePose(new ArPose(5000, 9400, 10));
      assertEquals(5000, sim.robot().getX(), 1);
      assertEquals(10, sim.robot().getTh(), 0.01);
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }

  @Test
  void threadedAndSynchronousModesGiveTheSameEstimates() throws Exception {
    List<ArPose> a = openLoopEstimates(UpdateMode.SYNCHRONOUS);
    List<ArPose> b = openLoopEstimates(UpdateMode.THREADED);
    assertTrue(a.size() > 20, "updates " + a.size());
    assertEquals(a, b);
  }

  /** Drives without looking at the pose, and collects every estimate. */
  private static List<ArPose> openLoopEstimates(UpdateMode mode) throws InterruptedException {
    SimulatedRobot sim = SimSetup.start(OFFICE, 5);
    try {
      ArRobot robot = sim.robot();
      ArSonarLocalizationTask loc =
          ArSonarLocalizationTask.builder(robot, OFFICE).mode(mode).seed(9).build();
      try {
        sim.runMillis(1000);
        loc.localizeRobotAtHomeBlocking();
        List<ArPose> out = new ArrayList<>();
        long seen = loc.getUpdateCount();
        for (int t = 0; t < 200; t++) {
          robot.setVel(t < 120 ? 400 : 100);
          robot.setRotVel(t < 120 ? 0 : 25);
          sim.runMillis(100);
          assertTrue(loc.awaitIdle(10_000), "localization thread caught up");
          if (loc.getUpdateCount() != seen) {
            seen = loc.getUpdateCount();
            out.add(loc.getEstimate().pose());
          }
        }
        assertEquals(0, loc.getDroppedUpdateCount());
        return out;
      } finally {
        loc.close();
      }
    } finally {
      SimSetup.stop(sim);
    }
  }

  /** Turns on the spot, through an action (so that ArActionLost can overrule it). */
  private static final class Spin extends ArAction {
    private final ArActionDesired d = new ArActionDesired();

    Spin() {
      super("spin");
    }

    @Override
    public ArActionDesired fire(ArActionDesired current) {
      d.reset();
      d.setVel(0);
      d.setRotVel(30);
      return d;
    }
  }

  @Test
  void aKidnappedRobotIsLostAndArActionLostStopsIt() {
    SimulatedRobot sim = SimSetup.start(OFFICE, 3);
    try {
      ArRobot robot = sim.robot();
      ArSonarLocalizationTask loc = sync(robot, OFFICE, 3);
      loc.getParams().get("RecoverOnFail").setBool(false);
      AtomicInteger lost = new AtomicInteger();
      AtomicInteger failed = new AtomicInteger();
      loc.addLostCB(lost::incrementAndGet);
      loc.addFailedLocalizationCB(n -> failed.set(n));
      sim.runMillis(1000);
      assertTrue(loc.localizeRobotAtHomeBlocking());
      robot.addAction(new Spin(), 10);
      robot.addAction(new ArActionLost(loc), 150);
      sim.runMillis(3000);
      assertFalse(loc.getRobotIsLostFlag());
      assertTrue(Math.abs(robot.getRotVel()) > 20, "spinning while localized");
      // Carried into the middle of the kitchen: nothing matches any more.
      SimRobot body = sim.sim();
      body.setTruePose(new ArPose(3750, 3000, 0));
      assertTrue(
          sim.runUntil(loc::getRobotIsLostFlag, Duration.ofSeconds(60)), "noticed it is lost");
      assertEquals(1, lost.get());
      assertTrue(failed.get() >= loc.getParams().get("FailuresToLost").getInt());
      assertEquals(LockState.LOST, loc.getLockState());
      sim.runMillis(2000);
      assertEquals(0, robot.getRotVel(), 1, "ArActionLost stopped the robot");
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }

  @Test
  void aKidnappedRobotRecoversFromTheParticlesInjectedWhileLost() {
    ArMap columbia = SimSetup.columbia();
    SimulatedRobot sim = SimSetup.start(columbia, 5);
    try {
      ArRobot robot = sim.robot();
      ArSonarLocalizationTask loc = sync(robot, columbia, 5);
      AtomicInteger lost = new AtomicInteger();
      loc.addLostCB(lost::incrementAndGet);
      sim.runMillis(1000);
      assertTrue(loc.localizeRobotAtHomeBlocking());
      // Carried from the home room to the north end of the east hallway, then driven south.
      // (Recovery is likely, not certain: in 5 of the seeds 1-8 this works within the time, seeds
      // 1, 5, 6, 7 and 8; with the likelihood field before wall faces it was 6 of 8.)
      ArPose carried = new ArPose(15750, 15150, 178);
      sim.sim().setTruePose(carried);
      TrueRoute route =
          new TrueRoute(sim.sim(), SimSetup.truePath(columbia, carried, "Side door"), 400);
      robot.addAction(route, 50);
      double[] lastBad = {0};
      robot.addUserTask(
          "error",
          10,
          () -> {
            if (sim.sim().getTruePose().findDistanceTo(robot.getPose()) > 300) {
              lastBad[0] = robot.getClock().nanoTime() / 1e9;
            }
          });
      double t0 = robot.getClock().nanoTime() / 1e9;
      sim.runMillis(70_000);
      assertTrue(lost.get() >= 1, "noticed it was lost");
      assertEquals(LockState.LOCKED, loc.getLockState());
      double err = sim.sim().getTruePose().findDistanceTo(robot.getPose());
      assertTrue(err < 300, "localized again: error " + err + " mm");
      assertTrue(lastBad[0] - t0 < 45, "right again after " + (lastBad[0] - t0) + " s");
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }

  @Test
  void globalLocalizationFindsTheRobotWhileItDrives() {
    ArMap columbia = SimSetup.columbia();
    SimulatedRobot sim = SimSetup.start(columbia, 5);
    try {
      ArRobot robot = sim.robot();
      ArSonarLocalizationTask loc = sync(robot, columbia, 5);
      loc.getParams().setAdjustNumSamples(true);
      sim.runMillis(500);
      loc.startGlobalLocalization();
      assertEquals(LocalizationState.LOCALIZATION_INIT_COMPUTING, loc.getState());
      assertEquals(20000, loc.getCurrentNumSamples());
      // Drive (by the true pose) from the home room up the west corridor.
      TrueRoute route = new TrueRoute(sim.sim(), SimSetup.truePath(columbia, "Hallway 1"), 400);
      robot.addAction(route, 50);
      sim.runMillis(60_000);
      assertEquals(LocalizationState.LOCALIZATION_SUCCESS, loc.getState());
      ArPose t = sim.sim().getTruePose();
      ArPose e = robot.getPose();
      assertTrue(t.findDistanceTo(e) < 250, "true " + t + " estimate " + e);
      assertTrue(Math.abs(ArMath.subAngle(t.th(), e.th())) < Math.toDegrees(0.25));
      assertTrue(
          loc.getCurrentNumSamples() < 2000,
          "the count adapts once converged: " + loc.getCurrentNumSamples());
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }

  @Test
  void parametersComeFromTheConfig() throws Exception {
    SimulatedRobot sim = SimSetup.start(OFFICE, 6);
    try {
      ArSonarLocalizationTask loc = sync(sim.robot(), OFFICE, 6);
      var r =
          loc.getConfig()
              .parseText(
                  """
                  Section Localization
                  NumSamples 700
                  TriggerDistance 150
                  Section Path planning
                  PlanRes 50
                  """,
                  "arnl.p");
      assertEquals(700, loc.getNumSamples());
      assertEquals(150, loc.getParams().getTriggerDistance());
      assertEquals(1, r.warnings().size(), "the path planning section is not this task's");
      sim.runMillis(1000);
      loc.getParams().setNumSamplesAtInit(700);
      assertTrue(loc.localizeRobotAtHomeBlocking());
      assertEquals(700, loc.getCurrentNumSamples());
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }
}
