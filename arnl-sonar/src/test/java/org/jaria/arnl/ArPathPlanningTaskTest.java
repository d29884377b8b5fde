package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArPathPlanningTask.PlanMode;
import org.jaria.config.ArConfigException;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("slow")
class ArPathPlanningTaskTest {

  private static final ArMap OFFICE = ArMap.loadBundled("office");

  @Test
  void aGoalBehindADoorIsReachedThroughTheDoor() {
    PlanningRig r = PlanningRig.start(OFFICE, 2, PlanMode.SYNCHRONOUS);
    try {
      assertTrue(r.path().pathPlanToGoal("Lab Entrance"));
      assertEquals(PathPlanningState.MOVING_TO_GOAL, r.path().getState());
      List<ArPose> path = r.path().getCurrentPath();
      assertFalse(path.isEmpty());
      // The lab's door is the gap 10750..11750 in the wall at y = 8500.
      boolean throughDoor = false;
      for (int i = 1; i < path.size(); i++) {
        ArPose a = path.get(i - 1);
        ArPose b = path.get(i);
        if ((a.y() - 8500) * (b.y() - 8500) <= 0) {
          throughDoor = a.x() > 10900 && a.x() < 11600;
        }
      }
      assertTrue(throughDoor, "the path crosses the wall line inside the door");
      double[] closest = {Double.MAX_VALUE};
      r.robot()
          .addUserTask(
              "doorClearance",
              5,
              () -> {
                ArPose t = r.sim().sim().getTruePose();
                if (Math.abs(t.y() - 8500) < 300) {
                  closest[0] = Math.min(closest[0], Math.min(t.x() - 10750, 11750 - t.x()));
                }
              });
      assertTrue(r.finish(Duration.ofMinutes(3)));
      assertEquals(PathPlanningState.REACHED_GOAL, r.path().getState());
      ArPose t = r.sim().sim().getTruePose();
      assertTrue(t.findDistanceTo(new ArPose(11250, 7700)) < 250, "at " + t);
      assertTrue(Math.abs(t.th() - -90) < 15, "turned to the goal's heading: " + t);
      assertTrue(closest[0] > 212, "kept clear of the door frame: " + closest[0]);
    } finally {
      r.close();
    }
  }

  @Test
  void anObstacleAcrossThePathIsDrivenAround() {
    PlanningRig r = PlanningRig.start(OFFICE, 3, PlanMode.SYNCHRONOUS);
    try {
      // A 0.4 m x 1 m box against the north wall of the corridor, across the middle of it where
      // the planned path runs: only the southern metre of the corridor stays open.
      r.sim().world().injectBox(12000, 10000, 400, 1000, 0);
      double[] closest = {Double.MAX_VALUE};
      double[] passedAtY = {Double.NaN};
      int[] sensedMost = {0};
      r.robot()
          .addUserTask(
              "boxClearance",
              5,
              () -> {
                ArPose t = r.sim().sim().getTruePose();
                double dx = Math.max(0, Math.max(11800 - t.x(), t.x() - 12200));
                double dy = Math.max(0, Math.max(9500 - t.y(), t.y() - 10500));
                closest[0] = Math.min(closest[0], Math.hypot(dx, dy));
                if (Math.abs(t.x() - 12000) < 100) {
                  passedAtY[0] = t.y();
                }
                sensedMost[0] = Math.max(sensedMost[0], r.path().getSensedObstacles().size());
              });
      assertTrue(r.path().pathPlanToGoal("Corridor East"));
      List<ArPose> planned = r.path().getCurrentPath();
      assertTrue(
          planned.stream().anyMatch(p -> Math.abs(p.x() - 12000) < 200 && p.y() > 9400),
          "the first plan (made before the box was seen) runs through it");
      assertTrue(r.finish(Duration.ofMinutes(4)));
      assertEquals(PathPlanningState.REACHED_GOAL, r.path().getState(), r.path().getStatusString());
      assertTrue(sensedMost[0] > 0, "the sonar saw the box");
      assertTrue(passedAtY[0] < 9300, "passed the box on its free side, at y = " + passedAtY[0]);
      assertTrue(closest[0] > 212, "the robot's centre came within " + closest[0] + " mm");
    } finally {
      r.close();
    }
  }

  @Test
  void aBlockedCorridorEndsInFailedMoveWithAReason() {
    PlanningRig r = PlanningRig.start(OFFICE, 9, PlanMode.SYNCHRONOUS);
    try {
      // A cupboard across the whole corridor: Corridor East cannot be reached.
      r.sim().world().injectBox(12000, 9500, 400, 2000, 0);
      double[] closest = {Double.MAX_VALUE};
      r.robot()
          .addUserTask(
              "boxClearance",
              5,
              () -> {
                ArPose t = r.sim().sim().getTruePose();
                closest[0] = Math.min(closest[0], Math.max(0, 11800 - t.x()));
              });
      List<ArPose> failed = new ArrayList<>();
      r.path().addGoalFailedCB(failed::add);
      long t0 = r.robot().getClock().nanoTime();
      assertTrue(r.path().pathPlanToGoal("Corridor East"));
      assertTrue(r.finish(Duration.ofMinutes(3)), "gave up in time");
      double seconds = (r.robot().getClock().nanoTime() - t0) / 1e9;
      assertEquals(PathPlanningState.FAILED_MOVE, r.path().getState(), r.path().getStatusString());
      assertEquals(1, failed.size());
      assertTrue(
          r.path().getFailureString().contains("blocked")
              || r.path().getFailureString().contains("no progress"),
          r.path().getFailureString());
      assertTrue(r.path().getReplanCount() > 0, "replanned before giving up");
      assertTrue(seconds < 120, "took " + seconds + " s");
      assertTrue(closest[0] > 150, "stopped short of the cupboard: " + closest[0] + " mm");
      r.sim().runMillis(1500);
      assertEquals(0, r.robot().getVel(), 10, "stopped");
      assertEquals(0, r.robot().getRotVel(), 3, "stopped");
    } finally {
      r.close();
    }
  }

  /**
   * A loop: a 12 m x 7 m hall around a 6 m x 3.5 m block, leaving a 2 m corridor to the south and a
   * 1.5 m one to the north.
   */
  private static ArMap loop() {
    ArMap m = new ArMap();
    m.setLines(
        List.of(
            new ArLineSegment(0, 0, 12000, 0),
            new ArLineSegment(12000, 0, 12000, 7000),
            new ArLineSegment(12000, 7000, 0, 7000),
            new ArLineSegment(0, 7000, 0, 0),
            new ArLineSegment(3000, 2000, 9000, 2000),
            new ArLineSegment(9000, 2000, 9000, 5500),
            new ArLineSegment(9000, 5500, 3000, 5500),
            new ArLineSegment(3000, 5500, 3000, 2000)));
    m.addMapObject(ArMapObject.robotHome("", 1500, 3500, 0));
    m.addMapObject(ArMapObject.goal("East", 10500, 3500));
    return m;
  }

  @Test
  void aBlockedPathIsReplannedTheOtherWayRound() {
    ArMap loop = loop();
    PlanningRig r = PlanningRig.start(loop, 10, PlanMode.SYNCHRONOUS);
    try {
      assertTrue(r.path().pathPlanToGoal("east"));
      assertTrue(
          r.path().getCurrentPath().stream().allMatch(p -> p.y() < 4000),
          "the wide southern corridor is planned first");
      // The southern corridor is closed by a box nobody put on the map.
      r.sim().world().injectBox(6000, 1000, 400, 2000, 0);
      double[] northMost = {0};
      r.robot()
          .addUserTask(
              "north",
              5,
              () -> northMost[0] = Math.max(northMost[0], r.sim().sim().getTruePose().y()));
      assertTrue(r.finish(Duration.ofMinutes(4)));
      assertEquals(PathPlanningState.REACHED_GOAL, r.path().getState(), r.path().getStatusString());
      assertTrue(northMost[0] > 5600, "went round by the north: " + northMost[0]);
      assertTrue(r.path().getReplanCount() > 0, "replanned");
      assertTrue(
          r.path().getCurrentPath().stream().anyMatch(p -> p.y() > 5500),
          "the path in use goes north");
      assertTrue(r.sim().sim().getTruePose().findDistanceTo(new ArPose(10500, 3500)) < 250);
    } finally {
      r.close();
    }
  }

  @Test
  void manyIntermediateGoalsDoNotDegradeLocalization() {
    // The thesis's robot got lost when given many intermediate goals (§7.1): here a goal never
    // touches localization, so eight short legs are as good as one long one.
    PlanningRig r = PlanningRig.start(OFFICE, 8, PlanMode.SYNCHRONOUS);
    try {
      double worst = 0;
      for (double x = 4500; x <= 25500; x += 3000) {
        assertTrue(r.path().pathPlanToPose(new ArPose(x, 9500, 0), false));
        assertTrue(r.finish(Duration.ofMinutes(1)));
        assertEquals(
            PathPlanningState.REACHED_GOAL, r.path().getState(), r.path().getStatusString());
        worst = Math.max(worst, r.sim().sim().getTruePose().findDistanceTo(r.robot().getPose()));
      }
      assertTrue(worst < 150, "localization error at the goals reached " + worst + " mm");
      assertEquals(LockState.LOCKED, r.loc().getLockState());
    } finally {
      r.close();
    }
  }

  @Test
  void losingLocalizationFailsTheGoalAndArActionLostStopsTheRobot() {
    PlanningRig r = PlanningRig.start(OFFICE, 11, PlanMode.SYNCHRONOUS);
    try {
      r.loc().getParams().get("RecoverOnFail").setBool(false);
      r.path().getPathPlanActionGroup().addAction(new ArActionLost(r.loc(), r.path()), 150);
      List<ArPose> failed = new ArrayList<>();
      r.path().addGoalFailedCB(failed::add);
      assertTrue(r.path().pathPlanToGoal("Corridor East"));
      r.sim().runMillis(5000);
      assertEquals(PathPlanningState.MOVING_TO_GOAL, r.path().getState());
      // Carried into the kitchen: the sonar no longer fits the pose the robot believes.
      r.sim().sim().setTruePose(new ArPose(3750, 3000, 0));
      assertTrue(r.finish(Duration.ofSeconds(60)), "the goal ended");
      assertEquals(PathPlanningState.FAILED_MOVE, r.path().getState());
      assertTrue(
          r.path().getFailureString().contains("localization lost"), r.path().getFailureString());
      assertEquals(1, failed.size());
      assertTrue(r.loc().getRobotIsLostFlag());
      r.sim().runMillis(2000);
      assertEquals(0, r.robot().getVel(), 10, "stopped");
      assertEquals(0, r.robot().getRotVel(), 3, "stopped");
    } finally {
      r.close();
    }
  }

  @Test
  void cancellingAndReplacingGoalsInterruptThem() {
    PlanningRig r = PlanningRig.start(OFFICE, 4, PlanMode.SYNCHRONOUS);
    try {
      List<ArPose> interrupted = new ArrayList<>();
      List<ArPose> fresh = new ArrayList<>();
      int[] finished = {0};
      r.path().addGoalInterruptedCB(interrupted::add);
      r.path().addNewGoalCB(fresh::add);
      r.path().addGoalFinishedCB(() -> finished[0]++);
      assertTrue(r.path().pathPlanToGoal("Corridor East"));
      r.sim().runMillis(3000);
      assertTrue(r.robot().getVel() > 100, "moving");
      assertTrue(r.path().pathPlanToPose(new ArPose(4000, 9500, 180), true));
      assertEquals(1, interrupted.size(), "the first goal was replaced");
      assertEquals(26000, interrupted.get(0).x(), 1);
      r.sim().runMillis(2000);
      r.path().cancelPathPlan();
      assertEquals(PathPlanningState.ABORTED_PATHPLAN, r.path().getState());
      assertEquals(2, interrupted.size());
      assertEquals(2, fresh.size());
      assertEquals(2, finished[0]);
      r.sim().runMillis(3000);
      assertEquals(0, r.robot().getVel(), 20, "stopped after the cancel");
      assertTrue(r.path().getLocalSearchArea().size() == 4);
    } finally {
      r.close();
    }
  }

  @Test
  void refusesGoalsOffTheMapAndUnknownNames() {
    PlanningRig r = PlanningRig.start(OFFICE, 5, PlanMode.SYNCHRONOUS);
    try {
      assertFalse(r.path().pathPlanToPose(new ArPose(90_000, 0, 0), false));
      assertEquals(PathPlanningState.GOAL_OUT_OF_BOUNDS, r.path().getState());
      assertTrue(r.path().getFailureString().contains("outside the map"));
      assertFalse(r.path().pathPlanToPose(new ArPose(13500, 6500, 0), false));
      assertEquals(PathPlanningState.GOAL_IN_OBSTACLE, r.path().getState());
      assertFalse(r.path().pathPlanToPose(new ArPose(3000, 8500, 0), false), "on a wall");
      assertEquals(PathPlanningState.GOAL_IN_OBSTACLE, r.path().getState());
      assertTrue(r.path().getStatusString().contains("too close"), r.path().getStatusString());
      assertFalse(r.path().pathPlanToGoal("Room 999"));
      assertTrue(r.path().getStatusString().contains("Room 101"), "lists the goals");
    } finally {
      r.close();
    }
  }

  @Test
  void threadedPlanningReachesTheGoalToo() {
    PlanningRig r = PlanningRig.start(OFFICE, 6, PlanMode.THREADED);
    try {
      assertTrue(r.path().pathPlanToGoal("Room 101"));
      assertTrue(r.finish(Duration.ofMinutes(3)));
      assertEquals(PathPlanningState.REACHED_GOAL, r.path().getState(), r.path().getStatusString());
    } finally {
      r.close();
    }
  }

  @Test
  void parametersLoadFromAnArnlStyleFile() throws Exception {
    PlanningRig r = PlanningRig.start(OFFICE, 7, PlanMode.SYNCHRONOUS);
    try {
      r.path()
          .getConfig()
          .parseText("Section Path planning\nMaxSpeed 250\nGoalDistanceTolerance 150\n", "arnl.p");
      assertEquals(250, r.path().getParams().getMaxSpeed());
      assertTrue(r.path().pathPlanToGoal("Corridor West"));
      double[] top = {0};
      r.robot().addUserTask("speed", 5, () -> top[0] = Math.max(top[0], r.robot().getVel()));
      assertTrue(r.finish(Duration.ofMinutes(2)));
      assertEquals(PathPlanningState.REACHED_GOAL, r.path().getState());
      assertTrue(top[0] <= 280, "kept to MaxSpeed: " + top[0]);
      ArConfigException e =
          org.junit.jupiter.api.Assertions.assertThrows(
              ArConfigException.class,
              () ->
                  r.path()
                      .getConfig()
                      .parseText("Section Path planning\nMaxSpeed fast\n", "bad.p"));
      assertEquals(2, e.getLine());
      assertEquals(250, r.path().getParams().getMaxSpeed());
    } finally {
      r.close();
    }
  }
}
