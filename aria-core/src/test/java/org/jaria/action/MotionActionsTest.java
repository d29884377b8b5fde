package org.jaria.action;

import static org.jaria.action.ActionRig.fire;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArListPos;
import org.junit.jupiter.api.Test;

/** Actions that drive: stop, constant velocity, input, goto, drive distance, ratios. */
class MotionActionsTest {

  private final ActionRig ar = new ActionRig();

  @Test
  void stopAndConstantVelocity() {
    ArActionDesired s = fire(ar.attach(new ArActionStop()));
    assertEquals(0, s.getVel(), 1e-9);
    assertEquals(1, s.getVelStrength(), 1e-9);
    assertEquals(0, s.getDeltaHeading(), 1e-9);
    assertEquals(1, s.getDeltaHeadingStrength(), 1e-9);
    ArActionConstantVelocity cv = ar.attach(new ArActionConstantVelocity());
    assertEquals("Constant Velocity", cv.getName());
    ArActionDesired c = fire(cv);
    assertEquals(400, c.getVel(), 1e-9);
    assertEquals(0, c.getDeltaHeading(), 1e-9);
    assertEquals(1, c.getDeltaHeadingStrength(), 1e-9);
  }

  @Test
  void inputAsksForWhatItWasTold() {
    ArActionInput in = ar.attach(new ArActionInput());
    assertFalse(fire(in).isAnythingDesired());
    in.setVel(200);
    in.setRotVel(10);
    ArActionDesired d = fire(in);
    assertEquals(200, d.getVel(), 1e-9);
    assertEquals(10, d.getRotVel(), 1e-9);
    in.deltaHeadingFromCurrent(30);
    assertEquals(30, fire(in).getDeltaHeading(), 1e-9);
    d = fire(in);
    assertEquals(0, d.getDeltaHeading(), 1e-9, "a change of heading is asked for once");
    assertEquals(200, d.getVel(), 1e-9, "the velocity persists");
    in.setHeading(45);
    d = fire(in);
    assertTrue(d.isHeadingSet());
    assertEquals(45, d.getHeading(), 1e-9);
    in.clear();
    assertFalse(fire(in).isAnythingDesired());
  }

  @Test
  void movementParametersSetOnlyWhatIsGiven() {
    ArActionMovementParameters mp = ar.attach(new ArActionMovementParameters());
    assertFalse(fire(mp).isAnythingDesired(), "all zero: nothing set");
    mp.setParameters(300, 200, 100, 400, 50, 60, 70);
    ArActionDesired d = fire(mp);
    assertEquals(300, d.getMaxVel(), 1e-9);
    assertEquals(-200, d.getMaxNegVel(), 1e-9);
    assertEquals(100, d.getTransAccel(), 1e-9);
    assertEquals(400, d.getTransDecel(), 1e-9);
    assertEquals(50, d.getMaxRotVel(), 1e-9);
    assertEquals(60, d.getRotAccel(), 1e-9);
    assertEquals(70, d.getRotDecel(), 1e-9);
    mp.disable();
    assertNull(fire(mp));
    mp.enableOnce();
    assertNotNull(fire(mp));
    assertNull(fire(mp), "enabled for one cycle only");
  }

  @Test
  void driveDistanceBrakesAndArrives() {
    ArActionDriveDistance dd = ar.attach(new ArActionDriveDistance());
    assertNull(fire(dd), "no distance yet");
    dd.setDistance(1000);
    ArActionDesired d = fire(dd);
    assertEquals(400, d.getVel(), 1e-9, "capped at the speed");
    assertEquals(0, d.getRotVel(), 1e-9);
    ar.rig.sip.setPos(900, 0, 0);
    ar.vel(200);
    assertEquals(Math.sqrt(100 * 200 * 2), fire(dd).getVel(), 1e-6);
    ar.rig.sip.setPos(1010, 0, 0);
    ar.vel(0);
    d = fire(dd);
    assertEquals(0, d.getVel(), 1e-9);
    assertTrue(dd.haveAchievedDistance());
    assertNull(fire(dd));
    dd.setDistance(-500);
    assertEquals(-400, fire(dd).getVel(), 1e-6, "backwards, capped at the speed");
    dd.cancelDistance();
    assertNull(fire(dd));
  }

  @Test
  void driveDistanceNeedsARobot() {
    ArActionDriveDistance dd = new ArActionDriveDistance();
    IllegalStateException e = assertThrows(IllegalStateException.class, () -> dd.setDistance(5));
    assertTrue(e.getMessage().contains("addAction"));
  }

  @Test
  void gotoPointsAtTheGoalAndBrakes() {
    ArActionGoto g = ar.attach(new ArActionGoto());
    ArActionDesired d = fire(g);
    assertTrue(g.haveAchievedGoal(), "ARIA's default goal is the origin, where the robot is");
    assertEquals(0, d.getVel(), 1e-9);
    g.setGoal(new ArPose(1000, 0));
    d = fire(g);
    assertTrue(d.isHeadingSet());
    assertEquals(0, d.getHeading(), 1e-9);
    assertEquals(400, d.getVel(), 1e-9);
    ar.pose(950, 0, 0);
    d = fire(g);
    assertEquals(0, d.getVel(), 1e-9, "within the close distance: stop");
    assertTrue(g.haveAchievedGoal());
  }

  @Test
  void gotoTurnsWhenSomethingAheadSlowsItDown() {
    ArActionGoto g = ar.attach(new ArActionGoto());
    g.setGoal(new ArPose(2000, 0));
    ArActionDesired limited = new ArActionDesired();
    limited.setMaxVel(100);
    ArActionDesired d = g.fire(limited);
    assertEquals(7, d.getDeltaHeading(), 1e-9);
    assertFalse(d.isHeadingSet());
    ar.pose(0, 0, 7);
    d = fire(g);
    assertEquals(-7, d.getDeltaHeading(), 1e-9, "turning back towards the goal");
  }

  @Test
  void gotoDrivesARoute() {
    ArActionGoto g = ar.attach(new ArActionGoto());
    g.setGoals(List.of(new ArPose(500, 0), new ArPose(500, 500)));
    assertEquals(0, fire(g).getHeading(), 1e-9);
    ar.pose(500, 0, 0);
    fire(g);
    assertFalse(g.haveAchievedGoal());
    assertEquals(1, g.getGoalIndex());
    ArActionDesired d = fire(g);
    assertEquals(90, d.getHeading(), 1e-6);
    ar.pose(500, 450, 90);
    fire(g);
    assertTrue(g.haveAchievedGoal());
  }

  @Test
  void gotoStraightForwardsBackwardsAndRelative() {
    ArActionGotoStraight g = ar.attach(new ArActionGotoStraight());
    assertNull(fire(g));
    g.setGoal(new ArPose(1000, 0));
    ArActionDesired d = fire(g);
    assertEquals(0, d.getHeading(), 1e-9);
    assertEquals(400, d.getVel(), 1e-9);
    g.setGoal(new ArPose(-1000, 0), true, true);
    d = fire(g);
    assertEquals(0, d.getHeading(), 1e-9, "backing: facing away from the goal");
    assertEquals(-400, d.getVel(), 1e-9);
    ar.pose(100, 100, 90);
    g.setGoalRel(1000, 90, false, true);
    assertEquals(-900, g.getGoal().x(), 1e-6);
    assertEquals(100, g.getGoal().y(), 1e-6);
    assertEquals(180, fire(g).getHeading(), 1e-6);
  }

  @Test
  void gotoStraightJustDistanceCountsTravel() {
    ArActionGotoStraight g = ar.attach(new ArActionGotoStraight());
    g.setGoal(new ArPose(1000, 0));
    ar.rig.sip.setPos(600, 0, 0);
    ar.vel(300);
    assertEquals(Math.sqrt(400 * 400.0), fire(g).getVel(), 1e-6);
    ar.rig.sip.setPos(1000, 0, 0);
    ar.vel(0);
    ArActionDesired d = fire(g);
    assertTrue(g.haveAchievedGoal());
    assertEquals(0, d.getVel(), 1e-9);
  }

  @Test
  void gotoStraightEncoderGoalStaysOnTheFloorWhenRelocalized() {
    ArActionGotoStraight global = ar.attach(new ArActionGotoStraight());
    ArActionGotoStraight encoder = ar.attach(new ArActionGotoStraight("enc", 400));
    ar.pose(5000, 0, 0);
    global.setGoal(new ArPose(6000, 0), false, false);
    encoder.setEncoderGoalRel(1000, 0, false, false);
    assertTrue(encoder.usingEncoderGoal());
    assertEquals(1000, encoder.getEncoderGoal().x(), 1e-6);
    ar.pose(5000, 0, 90); // localization: the robot was facing +y all along
    assertEquals(0, fire(global).getHeading(), 1e-6);
    assertEquals(90, fire(encoder).getHeading(), 1e-6);
  }

  @Test
  void gotoStraightTurnsInPlaceBeyondTheThreshold() {
    ArActionGotoStraight g = ar.attach(new ArActionGotoStraight());
    g.setTurnThreshold(30);
    g.setTurnSpeed(20);
    g.setGoal(new ArPose(0, 1000));
    ArActionDesired d = fire(g);
    assertEquals(90, d.getHeading(), 1e-6);
    assertEquals(0, d.getVelStrength(), 1e-9, "no forward motion yet");
    assertEquals(20, d.getMaxRotVel(), 1e-9);
    ar.pose(0, 0, 80);
    d = fire(g);
    assertEquals(400, d.getVel(), 1e-9);
    assertEquals(0, d.getMaxRotVelStrength(), 1e-9, "the turn-speed limit ends with the turn");
  }

  @Test
  void ratioInputMapsRatiosToSpeeds() {
    ArActionRatioInput in = ar.attach(new ArActionRatioInput());
    double vmax = ar.robot().getTransVelMax();
    in.setRatios(50, 0, 100);
    ArActionDesired d = fire(in);
    assertEquals(0.5 * vmax, d.getVel(), 1e-6);
    assertEquals(0, d.getRotVel(), 1e-9);
    in.setRatios(5, 50, 100);
    d = fire(in);
    assertEquals(0, d.getVel(), 1e-9, "inside the dead zone");
    assertEquals(25, d.getRotVel(), 1e-9, "half of 50 deg/s at rest");
    in.setRatios(-100, 0, 50);
    assertEquals(-vmax / 4 * 0.5, fire(in).getVel(), 1e-6);
    in.setRatios(500, -500, 500);
    assertEquals(100, in.getTransRatio(), 1e-9);
    assertEquals(-100, in.getRotRatio(), 1e-9);
    assertEquals(100, in.getThrottleRatio(), 1e-9);
  }

  @Test
  void ratioInputFireCallbacksRunLowestFirstAndActivationResets() {
    ArActionRatioInput in = ar.attach(new ArActionRatioInput());
    List<Integer> order = new ArrayList<>();
    in.addFireCallback(
        10,
        () -> {
          order.add(10);
          in.setTransRatio(80);
        });
    in.addFireCallback(
        1,
        () -> {
          order.add(1);
          in.setTransRatio(20);
        });
    in.setThrottleRatio(100);
    fire(in);
    assertEquals(List.of(1, 10), order);
    assertEquals(80, in.getTransRatio(), 1e-9, "the higher number has the last word");
    int[] activations = new int[2];
    in.addActivateCallback(() -> activations[0]++, ArListPos.LAST);
    in.addDeactivateCallback(() -> activations[1]++, ArListPos.FIRST);
    in.deactivate();
    assertEquals(0, in.getTransRatio(), 1e-9);
    in.setRatios(40, 40, 40);
    in.activate();
    assertEquals(0, in.getThrottleRatio(), 1e-9, "activation zeroes the ratios");
    assertEquals(1, activations[0]);
    assertEquals(1, activations[1]);
  }
}
