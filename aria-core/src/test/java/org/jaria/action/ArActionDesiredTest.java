package org.jaria.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The desire's own arithmetic: merging, averaging, headings and sanity checks. */
class ArActionDesiredTest {

  private static ArActionDesired vel(double v, double s) {
    ArActionDesired d = new ArActionDesired();
    d.setVel(v, s);
    return d;
  }

  @Test
  void mergeLetsALowerPriorityFillOnlyTheStrengthLeft() {
    ArActionDesired hi = vel(-400, 0.25);
    hi.merge(vel(0, 0.75 + 0.5)); // asks for more than is left
    assertEquals(1.0, hi.getVelStrength(), 1e-12);
    assertEquals(-100, hi.getVel(), 1e-9, "0.25*-400 + 0.75*0");
    hi.merge(vel(500, 0.5));
    assertEquals(-100, hi.getVel(), 1e-9, "a closed channel takes nothing more");
  }

  @Test
  void averagingWeighsValuesByStrengthAndCapsTheStrengthAtOne() {
    // Thesis table 5.58, steps 2-4: B (-100 at 1.0) and C (200 at 0.5) cancel out. The thesis
    // gives the pair strength 0.75 (the mean); ARIA's code sums strengths up to 1, which is what
    // we do. Both give the same final -100 once merged under A, as the resolver test checks.
    ArActionDesired avg = new ArActionDesired();
    avg.copyFrom(vel(-100, 1.0));
    avg.startAverage();
    avg.addAverage(vel(200, 0.5));
    avg.endAverage();
    assertEquals(0, avg.getVel(), 1e-9);
    assertEquals(1.0, avg.getVelStrength(), 1e-12);
  }

  @Test
  void averagingLimitChannelsKeepsTheMostRestrictive() {
    ArActionDesired a = new ArActionDesired();
    a.setMaxVel(300);
    a.setMaxNegVel(-200);
    a.startAverage();
    ArActionDesired b = new ArActionDesired();
    b.setMaxVel(150);
    b.setMaxNegVel(-400);
    a.addAverage(b);
    a.endAverage();
    assertEquals(150, a.getMaxVel(), 1e-9, "the slower forward limit");
    assertEquals(-200, a.getMaxNegVel(), 1e-9, "the slower backward limit");
  }

  @Test
  void mergingLimitsKeepsTheMostRestrictiveAndDecelerationsTheStrongest() {
    ArActionDesired a = new ArActionDesired();
    a.setMaxVel(300, 0.5, true);
    a.setTransDecel(200, 0.5, true);
    ArActionDesired b = new ArActionDesired();
    b.setMaxVel(500);
    b.setTransDecel(900);
    a.merge(b);
    assertEquals(300, a.getMaxVel(), 1e-9);
    assertEquals(900, a.getTransDecel(), 1e-9, "stopping harder is the restrictive choice");
  }

  @Test
  void anAbsoluteHeadingBecomesTheShortestChangeFromTheRobotsHeading() {
    ArActionDesired d = new ArActionDesired();
    d.setHeading(-170);
    assertTrue(d.isHeadingSet());
    d.accountForRobotHeading(170);
    assertFalse(d.isHeadingSet());
    assertEquals(20, d.getDeltaHeading(), 1e-9, "170 -> -170 is 20 degrees to the left");
    assertEquals(1.0, d.getDeltaHeadingStrength(), 1e-12);
  }

  @Test
  void deltaHeadingAndRotVelExcludeEachOtherWhenMerging() {
    ArActionDesired hi = new ArActionDesired();
    hi.setDeltaHeading(10, 0.5);
    ArActionDesired lo = new ArActionDesired();
    lo.setRotVel(40);
    lo.setDeltaHeading(30, 0.5);
    hi.merge(lo);
    assertEquals(20, hi.getDeltaHeading(), 1e-9, "(10*0.5 + 30*0.5) / 1.0");
    assertEquals(0, hi.getRotVelStrength(), 1e-12, "rotVel is not merged under a heading");
  }

  @Test
  void sanityCheckCorrectsImpossibleLimits() {
    ArActionDesired d = new ArActionDesired();
    d.setMaxVel(-50);
    d.setMaxNegVel(100);
    d.setTransAccel(0);
    d.setMaxRotVelPos(-3);
    d.sanityCheck("test");
    assertEquals(0, d.getMaxVel(), 1e-9);
    assertEquals(0, d.getMaxNegVel(), 1e-9);
    assertEquals(1, d.getTransAccel(), 1e-9);
    assertEquals(0, d.getMaxRotVelPos(), 1e-9);
  }

  @Test
  void nanAndInfiniteValuesAreDroppedNotPassedOn() {
    ArActionDesired d = new ArActionDesired();
    d.setVel(Double.NaN);
    d.setRotVel(Double.POSITIVE_INFINITY);
    d.setMaxVel(200, Double.NaN, true);
    d.setHeading(Double.NaN);
    assertEquals(0, d.getVelStrength(), 1e-12);
    assertEquals(0, d.getRotVelStrength(), 1e-12);
    assertEquals(0, d.getMaxVelStrength(), 1e-12);
    assertFalse(d.isHeadingSet());
    assertFalse(d.isAnythingDesired());
    d.sanityCheck("broken"); // logs and clears; must not throw
    d.setVel(100);
    assertEquals(100, d.getVel(), 1e-9, "the channel works again after a bad value");
  }

  @Test
  void strengthsAreClampedToTheUnitRange() {
    ArActionDesired d = vel(100, 7);
    assertEquals(1.0, d.getVelStrength(), 1e-12);
    d.setVel(100, 1e-9);
    assertEquals(0, d.getVelStrength(), 1e-12);
  }
}
