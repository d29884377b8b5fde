package org.jaria.tools.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** One line when the robot starts turning away from something, none while it keeps turning. */
class TurnReporterTest {

  @Test
  void aTurnIsReportedOnceWhenItStarts() {
    TurnReporter r = new TurnReporter();
    assertNull(r.update(1.0, 0, 900, 1500), "driving straight");
    assertEquals(
        "t=  1.1s  turning right, away from something 420 mm ahead", r.update(1.1, -30, 420, 1500));
    assertNull(r.update(1.2, -30, 400, 1500), "still the same turn");
    assertNull(r.update(1.3, 0, 2000, 1500), "straight again");
    assertEquals(
        "t=  4.0s  turning left, away from something 380 mm ahead", r.update(4.0, 25, -1, 380));
  }

  @Test
  void withNoReadingItStillSaysItTurns() {
    assertEquals("t=  2.0s  turning left", new TurnReporter().update(2.0, 20, -1, -1));
  }
}
