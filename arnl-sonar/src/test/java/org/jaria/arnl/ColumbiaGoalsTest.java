package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArPathPlanningTask.PlanMode;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Path planning over every goal of the bundled columbia map (a class of its own beside {@link
 * ArPathPlanningTaskTest}, so that the build's test JVMs run the two side by side).
 */
@Tag("slow")
class ColumbiaGoalsTest {

  @Test
  void everyReachableColumbiaGoalIsReachedAndTheImpossibleOnesFailFast() {
    ArMap columbia = SimSetup.columbia();
    PlanningRig r = PlanningRig.start(columbia, 1, PlanMode.SYNCHRONOUS);
    try {
      List<ArPose> done = new ArrayList<>();
      List<ArPose> failed = new ArrayList<>();
      r.path().addGoalDoneCB(done::add);
      r.path().addGoalFailedCB(failed::add);
      List<String> reachable =
          List.of(
              "Goal 3",
              "Goal 1",
              "Goal 2",
              "Hallway 1",
              "Hallway 2",
              "Side door",
              "Workshop",
              "Lobby door");
      for (String g : reachable) {
        assertTrue(r.path().pathPlanToGoal(g), g + ": " + r.path().getStatusString());
        assertTrue(r.finish(Duration.ofMinutes(5)), g + " finished");
        assertEquals(
            PathPlanningState.REACHED_GOAL, r.path().getState(), r.path().getStatusString());
        ArPose goal = columbia.findMapObject(g).orElseThrow().pose();
        assertTrue(
            r.sim().sim().getTruePose().findDistanceTo(goal) < 250,
            g + ": stopped at " + r.sim().sim().getTruePose());
      }
      assertEquals(reachable.size(), done.size());
      assertEquals(0, failed.size());
      // Every goal of the map is either reached above or refused below.
      assertEquals(reachable.size() + 2, columbia.getGoals().size());

      // The two goals that cannot be reached, failing at once (no simulated time passes):
      // "Impossible
      // Goal" lies in a walled-in alcove (about 0.8 m x 0.9 m) with no opening, "Inside Forbidden
      // Area" in a forbidden area.
      long before = r.robot().getClock().nanoTime();
      assertFalse(r.path().pathPlanToGoal("impossible goal"), "case-insensitive name");
      assertEquals(PathPlanningState.FAILED_PLAN, r.path().getState());
      assertTrue(r.path().getStatusString().contains("no path"), r.path().getStatusString());
      assertFalse(r.path().pathPlanToGoal("Inside Forbidden Area"));
      assertEquals(PathPlanningState.GOAL_IN_OBSTACLE, r.path().getState());
      assertTrue(r.path().getStatusString().contains("forbidden area"), r.path().getStatusString());
      assertEquals(before, r.robot().getClock().nanoTime(), "refused without driving");
      assertEquals(2, failed.size());
    } finally {
      r.close();
    }
  }
}
