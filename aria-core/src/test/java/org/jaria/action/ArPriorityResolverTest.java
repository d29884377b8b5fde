package org.jaria.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.action.ArResolver.PrioritizedAction;
import org.jaria.protocol.ArCommands;
import org.jaria.testing.FakeRobot;
import org.junit.jupiter.api.Test;

/** The priority resolver: strengths, priorities, limits, headings, misbehaving actions. */
class ArPriorityResolverTest {

  private final ArPriorityResolver resolver = new ArPriorityResolver();

  private static List<PrioritizedAction> list(Object... prioAndAction) {
    List<PrioritizedAction> l = new ArrayList<>();
    for (int i = 0; i < prioAndAction.length; i += 2) {
      l.add(new PrioritizedAction((Integer) prioAndAction[i], (ArAction) prioAndAction[i + 1]));
    }
    return l;
  }

  @Test
  void thesisTable558WorkedExample() {
    TestAction a = TestAction.vel("A", -400, 0.25);
    TestAction b = TestAction.vel("B", -100, 1.0);
    TestAction c = TestAction.vel("C", 200, 0.5);
    TestAction d = TestAction.vel("D", 500, 0.5);
    ArActionDesired r = resolver.resolve(list(4, a, 3, b, 3, c, 1, d), null);
    assertEquals(-100, r.getVel(), 1e-9);
    assertEquals(1.0, r.getVelStrength(), 1e-9);
    // A alone is what B and C were shown; D saw the channel already closed.
    assertEquals(-400, b.lastShown.getVel(), 1e-9);
    assertEquals(0.25, c.lastShown.getVelStrength(), 1e-9);
    assertEquals(1.0, d.lastShown.getVelStrength(), 1e-9);
  }

  @Test
  void thesisExampleActionDHasNoEffect() {
    TestAction a = TestAction.vel("A", -400, 0.25);
    TestAction b = TestAction.vel("B", -100, 1.0);
    TestAction c = TestAction.vel("C", 200, 0.5);
    ArActionDesired without = new ArActionDesired();
    without.copyFrom(resolver.resolve(list(4, a, 3, b, 3, c), null));
    for (double v : new double[] {-2000, 0, 500, 2000}) {
      TestAction d = TestAction.vel("D", v, 0.5);
      ArActionDesired with = resolver.resolve(list(4, a, 3, b, 3, c, 1, d), null);
      assertEquals(without.getVel(), with.getVel(), 1e-9);
      assertEquals(without.getVelStrength(), with.getVelStrength(), 1e-9);
    }
  }

  @Test
  void lowerPriorityFillsOnlyTheStrengthLeft() {
    TestAction hi = TestAction.vel("hi", 100, 0.6);
    TestAction lo = TestAction.vel("lo", 300, 1.0);
    ArActionDesired r = resolver.resolve(list(50, hi, 10, lo), null);
    assertEquals((0.6 * 100 + 0.4 * 300) / 1.0, r.getVel(), 1e-9);
    assertEquals(1.0, r.getVelStrength(), 1e-9);
  }

  @Test
  void equalPrioritiesAverageByStrength() {
    TestAction x = TestAction.vel("x", 100, 0.2);
    TestAction y = TestAction.vel("y", 400, 0.6);
    ArActionDesired r = resolver.resolve(list(5, x, 5, y), null);
    assertEquals((0.2 * 100 + 0.6 * 400) / 0.8, r.getVel(), 1e-9);
    assertEquals(0.8, r.getVelStrength(), 1e-9);
  }

  @Test
  void limitChannelsTakeTheMostRestrictiveAcrossPriorities() {
    TestAction hi =
        new TestAction(
            "hi",
            d -> {
              d.setMaxVel(500, 0.3, true);
              d.setMaxNegVel(-300);
              d.setTransDecel(200);
              d.setMaxRotVel(80);
            });
    TestAction lo =
        new TestAction(
            "lo",
            d -> {
              d.setMaxVel(200, 0.1, true);
              d.setMaxNegVel(-100);
              d.setTransDecel(900);
              d.setMaxRotVel(120);
            });
    ArActionDesired r = resolver.resolve(list(90, hi, 10, lo), null);
    assertEquals(200, r.getMaxVel(), 1e-9, "slowest forward limit, though weaker and lower");
    assertEquals(-100, r.getMaxNegVel(), 1e-9, "backward limit nearest to zero");
    assertEquals(900, r.getTransDecel(), 1e-9, "hardest deceleration");
    assertEquals(80, r.getMaxRotVel(), 1e-9);
  }

  @Test
  void limitChannelsTakeTheMostRestrictiveWithinOnePriority() {
    TestAction first = new TestAction("first", d -> d.setMaxVel(150));
    TestAction second = new TestAction("second", d -> d.setMaxVel(600));
    TestAction third = new TestAction("third", d -> d.setMaxVel(300, 0.2, true));
    ArActionDesired r = resolver.resolve(list(7, first, 7, second, 7, third), null);
    assertEquals(150, r.getMaxVel(), 1e-9, "the order within the priority does not matter");
    ArActionDesired r2 = resolver.resolve(list(7, third, 7, second, 7, first), null);
    assertEquals(150, r2.getMaxVel(), 1e-9);
  }

  @Test
  void limitWithoutOverrideAveragesInstead() {
    TestAction a = new TestAction("a", d -> d.setMaxVel(100, 0.5, false));
    TestAction b = new TestAction("b", d -> d.setMaxVel(300, 0.5, false));
    ArActionDesired r = resolver.resolve(list(3, a, 3, b), null);
    assertEquals(200, r.getMaxVel(), 1e-9);
  }

  @Test
  void absoluteHeadingBecomesAChangeFromTheRobotsHeading() {
    ActionRig ar = new ActionRig();
    ar.pose(0, 0, 30);
    TestAction h = new TestAction("h", d -> d.setHeading(-60));
    ArActionDesired r = resolver.resolve(list(10, h), ar.robot());
    assertEquals(-90, r.getDeltaHeading(), 1e-6);
    assertEquals(1.0, r.getDeltaHeadingStrength(), 1e-9);
    assertFalse(r.isHeadingSet());
    ar.pose(0, 0, 170);
    TestAction h2 = new TestAction("h2", d -> d.setHeading(-170));
    assertEquals(20, resolver.resolve(list(10, h2), ar.robot()).getDeltaHeading(), 1e-6);
  }

  @Test
  void headingAndRotVelExcludeEachOther() {
    TestAction turn = new TestAction("turn", d -> d.setDeltaHeading(10, 0.5));
    TestAction spin = new TestAction("spin", d -> d.setRotVel(40));
    ArActionDesired r = resolver.resolve(list(9, turn, 1, spin), null);
    assertEquals(10, r.getDeltaHeading(), 1e-9);
    assertEquals(0, r.getRotVelStrength(), 1e-9, "rot vel ignored once a heading is set");
  }

  @Test
  void aThrowingActionIsDeactivatedAndTheOthersStillCount() {
    TestAction bad =
        new TestAction(
            "bad",
            d -> {
              throw new IllegalStateException("student bug");
            });
    TestAction good = TestAction.vel("good", 250, 1.0);
    ArActionDesired r = resolver.resolve(list(80, bad, 20, good), null);
    assertFalse(bad.isActive());
    assertEquals(250, r.getVel(), 1e-9);
    resolver.resolve(list(80, bad, 20, good), null);
    assertEquals(1, bad.fired, "a deactivated action is not fired again");
    assertEquals(2, good.fired);
  }

  @Test
  void inactiveActionsAreNotFired() {
    TestAction off = TestAction.vel("off", 999, 1.0);
    off.deactivate();
    TestAction on = TestAction.vel("on", 100, 1.0);
    ArActionDesired r = resolver.resolve(list(9, off, 1, on), null);
    assertEquals(0, off.fired);
    assertEquals(100, r.getVel(), 1e-9);
  }

  @Test
  void theRobotsCycleSendsTheResolvedVelocity() {
    ActionRig ar = new ActionRig();
    ar.robot().addAction(new ArActionConstantVelocity("cv", 321), 25);
    FakeRobot fake = ar.rig.fake;
    fake.clearReceived();
    ar.run(300);
    assertTrue(
        fake.received(ArCommands.VEL).stream().anyMatch(x -> x.intArg() == 321),
        "VEL 321 sent: " + fake.received());
    assertEquals(321, ar.robot().getActionDesired().getVel(), 1e-9);
  }
}
