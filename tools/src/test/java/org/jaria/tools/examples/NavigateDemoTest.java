package org.jaria.tools.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.junit.jupiter.api.Test;

class NavigateDemoTest {

  @Test
  void drivesToSeveralGoalsInTurnAndReportsTheFinalError() {
    ByteArrayOutputStream buf = new ByteArrayOutputStream();
    PrintStream out = new PrintStream(buf, true, StandardCharsets.UTF_8);
    NavigateDemo.Result r =
        NavigateDemo.run(
            NavigateDemo.Options.of("office", List.of("Lab Entrance", "Kitchen")), out);
    String text = buf.toString(StandardCharsets.UTF_8);
    assertTrue(r.localized(), text);
    assertEquals(0, r.exitCode(), text);
    assertEquals(2, r.outcomes().size());
    for (NavigateDemo.GoalOutcome o : r.outcomes()) {
      assertTrue(o.reached(), o.toString());
      assertTrue(o.goalError() < 250, o.toString());
      assertTrue(o.locError() < 200, o.toString());
    }
    assertTrue(text.contains("Localized at home: yes"), text);
    assertTrue(text.contains("final position error"), text);
    assertTrue(text.contains("Done: 2 of 2 goals reached."), text);
  }

  @Test
  void unknownGoalsFailAndBadMapsAreExplained() {
    ByteArrayOutputStream buf = new ByteArrayOutputStream();
    PrintStream out = new PrintStream(buf, true, StandardCharsets.UTF_8);
    NavigateDemo.Result r =
        NavigateDemo.run(NavigateDemo.Options.of("office", List.of("Nowhere", "4000,9500")), out);
    assertEquals(1, r.exitCode());
    assertEquals(PathPlanningState.FAILED_PLAN, r.outcomes().get(0).state());
    assertTrue(r.outcomes().get(0).status().contains("no goal called 'Nowhere'"));
    assertTrue(r.outcomes().get(1).reached(), "a pose as x,y works too");
    int code =
        NavigateDemo.run(
            "/no/such/file.map",
            List.of("Goal 1"),
            null,
            new PrintStream(buf, true, StandardCharsets.UTF_8),
            0);
    assertEquals(2, code);
    String said = buf.toString(StandardCharsets.UTF_8);
    assertTrue(said.contains("there is no map file /no/such/file.map"), said);
    assertTrue(said.contains("bundled: office, hall, columbia"), said);
  }
}
