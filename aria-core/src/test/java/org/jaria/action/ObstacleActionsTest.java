package org.jaria.action;

import static org.jaria.action.ActionRig.fire;
import static org.jaria.action.ActionRig.frontSonarDistance;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.ArConfigPacket;
import org.junit.jupiter.api.Test;

/** Avoidance and limiter actions in hand-built sonar situations on a P3-DX. */
class ObstacleActionsTest {

  private final ActionRig ar = new ActionRig();

  @Test
  void avoidFrontDefaultsAreARIAs() {
    ArActionAvoidFront a = new ArActionAvoidFront();
    assertEquals("avoid front obstacles", a.getName());
    assertEquals(450, a.getObstacleDistance());
    assertEquals(200, a.getAvoidVelocity());
    assertEquals(15, a.getTurnAmount());
    assertTrue(a.getUseTableIRIfAvail());
  }

  @Test
  void avoidFrontWantsNothingWhenTheWayIsClear() {
    ArActionAvoidFront a = ar.attach(new ArActionAvoidFront());
    assertNull(fire(a));
    ar.sonar(3, 2000);
    assertNull(fire(a), "obstacle beyond 450 mm from the edge");
  }

  @Test
  void avoidFrontTurnsAwayFromAnObstacleOnTheRightAndSlows() {
    ArActionAvoidFront a = ar.attach(new ArActionAvoidFront());
    ar.sonar(4, 400); // front right
    ArActionDesired d = fire(a);
    assertNotNull(d);
    double dist = frontSonarDistance(400) - 250;
    assertEquals(15, d.getDeltaHeading(), 1e-9, "turn left, away from it");
    assertEquals(200 * dist / 450, d.getVel(), 1e-6);
    assertEquals(1.0, d.getVelStrength(), 1e-9);
  }

  @Test
  void avoidFrontStopsWhenCloserThanHalfTheDistanceAndKeepsItsDirection() {
    ArActionAvoidFront a = ar.attach(new ArActionAvoidFront());
    ar.sonar(3, 300); // front left: turn right
    ArActionDesired d = fire(a);
    assertEquals(-15, d.getDeltaHeading(), 1e-9);
    ar.sonar(3, 100);
    d = fire(a);
    assertEquals(0, d.getVel(), 1e-9, "closer than 225 mm from the edge: stop");
    ar.sonar(3, 5000).sonar(4, 300); // now the obstacle is on the right
    assertEquals(-15, fire(a).getDeltaHeading(), 1e-9, "keeps turning the way it started");
    ar.clearSonar();
    d = fire(a);
    assertNotNull(d, "one last desire to stop turning");
    assertEquals(0, d.getDeltaHeading(), 1e-9);
    assertEquals(1.0, d.getDeltaHeadingStrength(), 1e-9);
    assertNull(fire(a));
  }

  @Test
  void avoidFrontNearOfTheThesisStopsInsteadOfSlowing() {
    ArActionAvoidFront near = ar.attach(new ArActionAvoidFront("Avoid Front Near", 225, 0));
    ar.sonar(4, 150);
    ArActionDesired d = fire(near);
    assertEquals(0, d.getVel(), 1e-9);
    assertEquals(15, d.getDeltaHeading(), 1e-9);
  }

  @Test
  void avoidFrontStartsAfreshWhenAHigherPriorityTookTheHeading() {
    ArActionAvoidFront a = ar.attach(new ArActionAvoidFront());
    ar.sonar(3, 300);
    assertEquals(-15, fire(a).getDeltaHeading(), 1e-9);
    ar.sonar(3, 5000).sonar(4, 300);
    ArActionDesired taken = new ArActionDesired();
    taken.setDeltaHeading(5);
    assertEquals(15, a.fire(taken).getDeltaHeading(), 1e-9);
  }

  @Test
  void avoidSideTurnsAwayFromAWallBeside() {
    ArActionAvoidSide a = ar.attach(new ArActionAvoidSide());
    assertNull(fire(a));
    ar.sonar(0, 100); // left side
    ArActionDesired d = fire(a);
    assertEquals(-5, d.getDeltaHeading(), 1e-9);
    assertEquals(0, d.getVel(), 1e-9);
    ar.sonar(0, 5000).sonar(7, 100); // right side
    assertEquals(5, fire(a).getDeltaHeading(), 1e-9);
    ar.clearSonar();
    d = fire(a);
    assertEquals(0, d.getDeltaHeading(), 1e-9);
    assertEquals(1.0, d.getDeltaHeadingStrength(), 1e-9);
    assertNull(fire(a), "the manoeuvre is over");
  }

  @Test
  void turnTurnsMoreTheSlowerTheRobotGoes() {
    ArActionTurn t = ar.attach(new ArActionTurn());
    ar.vel(300);
    assertNull(fire(t), "faster than 200 mm/s: no turn");
    ar.sonar(4, 500).vel(50);
    assertEquals(15, fire(t).getDeltaHeading(), 1e-9, "full turn, away from the right");
    ar.vel(150);
    assertEquals(7.5, fire(t).getDeltaHeading(), 1e-6);
    ar.vel(250);
    assertNull(fire(t));
    ar.sonar(4, 5000).sonar(3, 500).vel(0);
    assertEquals(-15, fire(t).getDeltaHeading(), 1e-9, "new turn: away from the left");
  }

  @Test
  void limiterForwardsScalesTheMaximumSpeed() {
    ArActionLimiterForwards l = ar.attach(new ArActionLimiterForwards());
    assertNull(fire(l));
    ar.sonar(3, 400);
    double dist = frontSonarDistance(400) - 511 / 2.0;
    ArActionDesired d = fire(l);
    assertEquals(200 * (dist - 250) / 750, d.getMaxVel(), 1e-6);
    ar.sonar(3, 200);
    assertEquals(0, fire(l).getMaxVel(), 1e-9);
    ar.sonar(3, 1500);
    assertNull(fire(l), "beyond the box");
  }

  @Test
  void groupLimitersOfTheThesis() {
    ArActionLimiterForwards near =
        ar.attach(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250));
    ArActionLimiterForwards far =
        ar.attach(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400));
    ar.sonar(3, 500);
    double dist = frontSonarDistance(500) - 511 / 2.0;
    assertEquals(250 * (dist - 300) / 300, fire(near).getMaxVel(), 1e-6);
    assertEquals(400 * (dist - 300) / 800, fire(far).getMaxVel(), 1e-6);
  }

  @Test
  void limiterBackwardsLooksBehind() {
    ArActionLimiterBackwards l = ar.attach(new ArActionLimiterBackwards());
    assertEquals(-250, fire(l).getMaxNegVel(), 1e-9, "nothing behind: ARIA's backwards cap");
    ar.sonar(12, 300);
    double a = Math.toRadians(170);
    double dist = Math.hypot(-255 + 300 * Math.cos(a), 27 + 300 * Math.sin(a)) - 250;
    assertEquals(-250 * (dist - 250) / 350, fire(l).getMaxNegVel(), 1e-6);
    ar.sonar(12, 100);
    assertEquals(0, fire(l).getMaxNegVel(), 1e-9);
    ar.sonar(12, 5000).sonar(3, 100);
    assertEquals(-250, fire(l).getMaxNegVel(), 1e-9, "something in front does not matter");
  }

  @Test
  void limiterRotOnlyWhenAskedAndSomethingIsInsideTheRadius() {
    ArActionLimiterRot l = ar.attach(new ArActionLimiterRot());
    ar.sonar(0, 10);
    assertNull(fire(l), "off by default, as in ARIA");
    l.setParameters(true, 10);
    assertEquals(10, fire(l).getMaxRotVel(), 1e-9);
    l.setParameters(true, 0);
    assertEquals(0, fire(l).getMaxRotVel(), 1e-9);
    ar.clearSonar();
    assertNull(fire(l));
  }

  @Test
  void deceleratingLimiterIgnoresWhatItCanStopFor() {
    ArActionDeceleratingLimiter l = ar.attach(new ArActionDeceleratingLimiter());
    assertTrue(l.getForwards());
    ar.vel(300).sonar(3, 800);
    assertNull(fire(l));
    ar.vel(-300);
    assertNull(fire(l), "driving backwards: not its business");
  }

  @Test
  void deceleratingLimiterBrakesHarderWhenNeeded() {
    ArActionDeceleratingLimiter l = ar.attach(new ArActionDeceleratingLimiter());
    ar.vel(300).sonar(3, 350);
    double robotDecel = ar.robot().getTransDecel();
    double f = (300 - 200) / 800.0;
    double padding = 50 + 250 * f;
    double d = frontSonarDistance(350);
    double dist = d - 255.5 - 100 - padding;
    double need = 300.0 * 300 / dist / 2;
    assertTrue(need > robotDecel, "the situation needs more than the robot's " + robotDecel);
    ArActionDesired des = fire(l);
    assertNotNull(des);
    assertEquals(0, des.getMaxVel(), 1e-9);
    assertEquals(Math.min(need, 600), des.getTransDecel(), 1e-6);
  }

  @Test
  void deceleratingLimiterEmergencyInsideTheClearance() {
    ArActionDeceleratingLimiter l = ar.attach(new ArActionDeceleratingLimiter());
    ar.vel(300).sonar(3, 100);
    ArActionDesired des = fire(l);
    assertEquals(0, des.getMaxVel(), 1e-9);
    assertEquals(0, des.getVel(), 1e-9);
    int top = ar.robot().getOrigRobotConfig().getInt(ArConfigPacket.Field.TRANS_ACCEL_TOP);
    assertEquals(top, des.getTransDecel(), 1e-9, "the robot's top deceleration");
    assertFalse(ar.rig.fake.received().stream().anyMatch(x -> x.id() == 55));
    l.setParameters(100, 50, 50, 200, 400, 300, 1000, 600, true, 1500);
    ar.rig.fake.clearReceived();
    des = fire(l);
    assertEquals(1500, des.getTransDecel(), 1e-9);
    ar.run(100);
    assertFalse(ar.rig.fake.received(ArCommands.E_STOP).isEmpty(), "e-stop sent");
  }

  @Test
  void backwardsDeceleratingLimiterWatchesTheRear() {
    ArActionDeceleratingLimiter l =
        ar.attach(
            new ArActionDeceleratingLimiter(
                "back", ArActionDeceleratingLimiter.LimiterType.BACKWARDS));
    ar.vel(-300).sonar(12, 50);
    ArActionDesired des = fire(l);
    assertNotNull(des);
    assertEquals(0, des.getMaxNegVel(), 1e-9);
    assertEquals(0, des.getMaxVelStrength(), 1e-9);
  }
}
