package org.jaria.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.jaria.sim.robot.SrisimLaserSetup.Step;
import org.junit.jupiter.api.Test;

class SrisimLaserSetupTest {

  @Test
  void theArSimulatedLaserSequenceIsTheLaserSetUp() {
    SrisimLaserSetup s = new SrisimLaserSetup();
    assertEquals(Step.PENDING, s.accept(36, -90));
    assertEquals(Step.PENDING, s.accept(37, 90));
    assertEquals(Step.PENDING, s.accept(38, 50));
    assertEquals(Step.APPLY, s.accept(35, 2));
    assertEquals(-90, s.start());
    assertEquals(90, s.end());
    assertEquals(50, s.increment());
  }

  @Test
  void outOfSequenceTheNumbersKeepTheirArcosMeanings() {
    SrisimLaserSetup s = new SrisimLaserSetup();
    assertEquals(Step.ARCOS, s.accept(37, 2), "GRIPPERPACREQUEST on its own");
    assertEquals(Step.ARCOS, s.accept(35, 3), "ADSEL on its own");
    assertEquals(Step.ARCOS, s.accept(38, 1234), "GYROCALCW on its own");
    assertEquals(Step.PENDING, s.accept(36, -45));
    assertEquals(Step.ARCOS, s.accept(35, 1), "36 then 35: the sequence was broken");
    assertEquals(Step.ARCOS, s.accept(37, 45), "and stays broken until a new 36");
    assertEquals(Step.PENDING, s.accept(36, -45));
    assertEquals(Step.PENDING, s.accept(37, 45));
    s.reset();
    assertEquals(Step.ARCOS, s.accept(38, 100), "a new session forgets a half set-up");
  }
}
