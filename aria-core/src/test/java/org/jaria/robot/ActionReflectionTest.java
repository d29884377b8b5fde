package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.Consumer;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArResolver;
import org.jaria.protocol.ArCommands;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** How the actions' resolved desire reaches the robot: speeds, limits and accelerations. */
class ActionReflectionTest {

  private final LockstepRig rig = new LockstepRig();

  @BeforeEach
  void connect() {
    assertTrue(rig.connect());
    rig.run(300);
    rig.fake.clearReceived();
  }

  private List<FakeRobot.Received> sent(ArCommands c) {
    return rig.fake.received(c);
  }

  private int last(ArCommands c) {
    List<FakeRobot.Received> r = sent(c);
    assertFalse(r.isEmpty(), "no " + c + " was sent");
    return r.get(r.size() - 1).intArg();
  }

  /** An action whose desire the test sets. */
  private static ArAction wanting(String name, Consumer<ArActionDesired> setup) {
    return new ArAction(name) {
      private final ArActionDesired d = new ArActionDesired();

      @Override
      public ArActionDesired fire(ArActionDesired current) {
        d.reset();
        setup.accept(d);
        return d;
      }
    };
  }

  @Test
  void aLowerPriorityLimitCapsTheVelocitySent() {
    rig.robot.addAction(wanting("fast", d -> d.setVel(600)), 50);
    rig.robot.addAction(wanting("limit", d -> d.setMaxVel(250)), 40);
    rig.run(100);
    assertEquals(250, last(ArCommands.VEL));
  }

  @Test
  void theBackwardsLimitCapsNegativeVelocities() {
    rig.robot.addAction(wanting("back", d -> d.setVel(-500)), 50);
    rig.robot.addAction(wanting("limit", d -> d.setMaxNegVel(-120)), 40);
    rig.run(100);
    assertEquals(-120, last(ArCommands.VEL));
  }

  @Test
  void accelerationsAndDecelerationsGoOutAsSetaAndSetra() {
    rig.robot.addAction(
        wanting(
            "gentle",
            d -> {
              d.setVel(300);
              d.setTransAccel(111);
              d.setTransDecel(222);
              d.setRotAccel(33);
              d.setRotDecel(44);
            }),
        50);
    rig.run(100);
    List<Integer> seta = sent(ArCommands.SETA).stream().map(FakeRobot.Received::intArg).toList();
    List<Integer> setra = sent(ArCommands.SETRA).stream().map(FakeRobot.Received::intArg).toList();
    assertTrue(seta.contains(111), "SETA +111 (acceleration): " + seta);
    assertTrue(seta.contains(-222), "SETA -222 (deceleration): " + seta);
    assertTrue(setra.contains(33), "SETRA +33: " + setra);
    assertTrue(setra.contains(-44), "SETRA -44: " + setra);
  }

  @Test
  void anActionsMaximumRotationalVelocityIsSentAsSetrv() {
    rig.robot.addAction(
        wanting(
            "slow turns",
            d -> {
              d.setRotVel(10);
              d.setMaxRotVel(27);
            }),
        50);
    rig.run(100);
    assertEquals(27, last(ArCommands.SETRV));
    assertEquals(10, last(ArCommands.RVEL));
  }

  @Test
  void perDirectionLimitsClampRotationalVelocityOnTheirSideOnly() {
    rig.robot.addAction(wanting("left", d -> d.setRotVel(60)), 50);
    rig.robot.addAction(
        wanting(
            "limits",
            d -> {
              d.setMaxRotVelPos(15);
              d.setMaxRotVelNeg(40);
            }),
        40);
    rig.run(100);
    assertEquals(15, last(ArCommands.RVEL), "counter-clockwise is capped by maxRotVelPos");

    LockstepRig other = new LockstepRig();
    assertTrue(other.connect());
    other.robot.addAction(wanting("right", d -> d.setRotVel(-60)), 50);
    other.robot.addAction(
        wanting(
            "limits",
            d -> {
              d.setMaxRotVelPos(15);
              d.setMaxRotVelNeg(40);
            }),
        40);
    other.run(100);
    List<FakeRobot.Received> rvel = other.fake.received(ArCommands.RVEL);
    assertEquals(-40, rvel.get(rvel.size() - 1).intArg(), "clockwise is capped by maxRotVelNeg");
  }

  @Test
  void aHeadingTurnIsSlowedToThePerDirectionLimitOfItsSide() {
    rig.robot.addAction(wanting("turn left", d -> d.setDeltaHeading(90)), 50);
    rig.robot.addAction(wanting("limit", d -> d.setMaxRotVelPos(12)), 40);
    rig.run(100);
    assertEquals(90, last(ArCommands.HEAD));
    assertEquals(12, last(ArCommands.SETRV), "the turn runs at most 12 deg/s");
  }

  @Test
  void aZeroLimitOnTheTurningSideStopsTheTurn() {
    rig.robot.addAction(wanting("turn right", d -> d.setDeltaHeading(-45)), 50);
    rig.robot.addAction(wanting("no right turns", d -> d.setMaxRotVelNeg(0)), 40);
    rig.run(100);
    assertTrue(sent(ArCommands.HEAD).isEmpty(), "no HEAD while turning that way is forbidden");
    assertEquals(0, last(ArCommands.RVEL));
  }

  @Test
  void aNonFiniteDesireIsDroppedAndTheOthersStillDrive() {
    rig.robot.addAction(wanting("broken", d -> d.setVel(Double.NaN)), 60);
    rig.robot.addAction(wanting("sane", d -> d.setVel(180)), 50);
    rig.run(100);
    assertEquals(180, last(ArCommands.VEL));
  }

  @Test
  void aCustomResolverDecidesWhatIsSent() {
    ArResolver always77 =
        new ArResolver() {
          private final ArActionDesired out = new ArActionDesired();

          @Override
          public ArActionDesired resolve(List<PrioritizedAction> actions, ArRobot robot) {
            out.reset();
            out.setVel(77);
            return out;
          }

          @Override
          public String getName() {
            return "always 77";
          }
        };
    rig.robot.setResolver(always77);
    rig.robot.addAction(wanting("ignored", d -> d.setVel(500)), 50);
    rig.run(100);
    assertEquals(77, last(ArCommands.VEL));
  }
}
