package org.jaria.range;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.jaria.range.ArSonarAutoDisabler.Action;
import org.jaria.range.ArSonarAutoDisabler.View;
import org.junit.jupiter.api.Test;

/** ARIA's sonar auto-disabling rules as values. */
class ArSonarAutoDisablerDecisionTest {

  @Test
  void sonarGoOffOnlyAfterASecondStandingStill() {
    assertEquals(
        Action.NONE, ArSonarAutoDisabler.decide(new View(true, false, 0, 0, true, 1000), false));
    assertEquals(
        Action.DISABLE, ArSonarAutoDisabler.decide(new View(true, false, 0, 0, true, 1001), false));
    assertEquals(
        Action.NONE, ArSonarAutoDisabler.decide(new View(false, false, 0, 0, true, 5000), false));
  }

  @Test
  void sonarComeOnWhenTheRobotMovesOrWantsToWithMotorsOn() {
    assertEquals(
        Action.ENABLE, ArSonarAutoDisabler.decide(new View(false, true, 0, 0, true, 0), false));
    assertEquals(
        Action.ENABLE, ArSonarAutoDisabler.decide(new View(false, false, 5, 0, true, 0), false));
    assertEquals(
        Action.ENABLE, ArSonarAutoDisabler.decide(new View(false, false, 0, -2, true, 0), false));
    assertEquals(
        Action.NONE,
        ArSonarAutoDisabler.decide(new View(false, true, 0, 0, false, 0), false),
        "motors off");
    assertEquals(
        Action.NONE,
        ArSonarAutoDisabler.decide(new View(false, false, 3.9, 0.9, true, 0), false),
        "creeping is stopped");
  }

  @Test
  void supressedKeepsThemOff() {
    assertEquals(
        Action.DISABLE, ArSonarAutoDisabler.decide(new View(true, true, 300, 0, true, 0), true));
    assertEquals(
        Action.NONE, ArSonarAutoDisabler.decide(new View(false, true, 300, 0, true, 0), true));
  }
}
