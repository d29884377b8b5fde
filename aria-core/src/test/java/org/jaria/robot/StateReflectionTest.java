package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.DirectMotion.RotType;
import org.jaria.robot.DirectMotion.TransType;
import org.junit.jupiter.api.Test;

/**
 * State reflection as a function: given requests, status, time and memory, which commands does a
 * cycle send? Plain values in, plain values out; no robot, no connection.
 */
class StateReflectionTest {

  private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);
  private static final MotionLimits.Values LIMITS =
      new MotionLimits.Values(true, true, 500, 400, 100, 300, 300, 100, 100);
  private static final StateReflection.Settings SETTINGS =
      new StateReflection.Settings(true, 500 * MS, 0, true, 20, LIMITS);
  private static final RobotStatus STILL = RobotStatus.initial(List.of());
  private static final ArActionDesired NO_DESIRE = new ArActionDesired();

  private static CycleCommands cycle(
      long nowMs, DirectMotion direct, ArActionDesired desired, ReflectionMemory before) {
    return StateReflection.decide(
        new StateReflection.Inputs(nowMs * MS, direct, desired, STILL, SETTINGS), before);
  }

  private static DirectMotion vel(double v, long atMs) {
    return DirectMotion.NONE.withTrans(TransType.VEL, v, 0, atMs * MS, ArPose.ORIGIN);
  }

  private static final ReflectionMemory CONNECTED = ReflectionMemory.EMPTY.connected(0);

  @Test
  void aNewVelocityGoesOutWithTheLimitsItNeeds() {
    CycleCommands c = cycle(100, vel(300, 50), NO_DESIRE, CONNECTED);
    assertEquals(
        List.of(
            MotionCommand.of(ArCommands.SETV, 400),
            MotionCommand.of(ArCommands.SETA, 300),
            MotionCommand.of(ArCommands.SETA, -300),
            MotionCommand.of(ArCommands.VEL, 300),
            MotionCommand.of(ArCommands.SETRV, 100),
            MotionCommand.of(ArCommands.SETRA, 100),
            MotionCommand.of(ArCommands.SETRA, -100)),
        c.commands());
    assertTrue(c.tryingToMove());
    assertEquals(100 * MS, c.memory().sentAt().trans());
  }

  @Test
  void anUnchangedVelocityWaitsForTheRefreshTime() {
    CycleCommands first = cycle(100, vel(300, 50), NO_DESIRE, CONNECTED);
    CycleCommands second = cycle(200, vel(300, 50), NO_DESIRE, first.memory());
    assertEquals(List.of(), second.commands());
    CycleCommands refreshed = cycle(600, vel(300, 50), NO_DESIRE, second.memory());
    assertEquals(List.of(MotionCommand.of(ArCommands.VEL, 300)), refreshed.commands());
  }

  @Test
  void aVelocityAboveTheMaximumIsCapped() {
    CycleCommands c = cycle(100, vel(900, 50), NO_DESIRE, CONNECTED);
    assertTrue(c.commands().contains(MotionCommand.of(ArCommands.VEL, 400)));
  }

  @Test
  void aQuietRobotGetsAPulseAfterTheRefreshTime() {
    ReflectionMemory m = CONNECTED;
    CycleCommands early = cycle(400, DirectMotion.NONE, NO_DESIRE, m);
    assertFalse(early.commands().contains(MotionCommand.of(ArCommands.PULSE)));
    CycleCommands late = cycle(501, DirectMotion.NONE, NO_DESIRE, early.memory());
    assertEquals(MotionCommand.of(ArCommands.PULSE), last(late.commands()));
    assertEquals(501 * MS, late.memory().sentAt().pulse());
  }

  @Test
  void aMoveGoesOutOnceAndIsThenBeingDriven() {
    DirectMotion move =
        DirectMotion.NONE.withTrans(TransType.DIST_NEW, 500, 0, 50 * MS, ArPose.ORIGIN);
    CycleCommands c = cycle(100, move, NO_DESIRE, CONNECTED);
    assertTrue(c.commands().contains(MotionCommand.of(ArCommands.MOVE, 500)));
    assertEquals(TransType.DIST, c.direct().transType());
    CycleCommands next = cycle(200, c.direct(), NO_DESIRE, c.memory());
    assertFalse(next.commands().contains(MotionCommand.of(ArCommands.MOVE, 500)));
  }

  @Test
  void withoutAMoveCommandADistanceIsDrivenByVelocity() {
    StateReflection.Settings noMove =
        new StateReflection.Settings(true, 500 * MS, 0, false, 20, LIMITS);
    DirectMotion move =
        DirectMotion.NONE.withTrans(TransType.DIST_NEW, 1000, 0, 50 * MS, ArPose.ORIGIN);
    CycleCommands c =
        StateReflection.decide(
            new StateReflection.Inputs(100 * MS, move, NO_DESIRE, STILL, noMove), CONNECTED);
    // sqrt(2 * 200 mm/s² * 1000 mm) = 632 mm/s, capped at the 400 mm/s maximum.
    assertTrue(c.commands().contains(MotionCommand.of(ArCommands.VEL, 400)), c.toString());
    assertEquals(TransType.DIST, c.direct().transType());
  }

  @Test
  void theActionsDesireIsSentWithinItsOwnLimit() {
    ArActionDesired d = new ArActionDesired();
    d.setVel(350);
    d.setMaxVel(150);
    d.setRotVel(20);
    CycleCommands c = cycle(100, DirectMotion.NONE, d, CONNECTED);
    assertTrue(c.commands().contains(MotionCommand.of(ArCommands.VEL, 150)), c.toString());
    assertTrue(c.commands().contains(MotionCommand.of(ArCommands.RVEL, 20)), c.toString());
    assertTrue(c.tryingToMove());
  }

  @Test
  void whenMotionCommandsLetGoTheActionsValueGoesOutAtOnce() {
    ArActionDesired d = new ArActionDesired();
    d.setVel(200);
    CycleCommands actions = cycle(100, DirectMotion.NONE, d, CONNECTED);
    CycleCommands direct = cycle(200, vel(300, 150), d, actions.memory());
    assertTrue(direct.commands().contains(MotionCommand.of(ArCommands.VEL, 300)));
    CycleCommands back = cycle(300, DirectMotion.NONE, d, direct.memory());
    assertEquals(List.of(MotionCommand.of(ArCommands.VEL, 200)), back.commands());
  }

  @Test
  void aHeadingIsSentInTheRobotsOwnFrame() {
    DirectMotion head = DirectMotion.NONE.withRot(RotType.HEADING, 90, 50 * MS);
    // The status carries the encoder→global transform: here the encoder frame is turned 30°.
    RobotStatus turned =
        STILL.toBuilder()
            .encoderTransform(ArTransform.between(ArPose.ORIGIN, new ArPose(0, 0, 30)))
            .pose(new ArPose(0, 0, 30))
            .build();
    CycleCommands c =
        StateReflection.decide(
            new StateReflection.Inputs(100 * MS, head, NO_DESIRE, turned, SETTINGS), CONNECTED);
    // Global 90° with the encoder frame turned 30° is 60° for the robot.
    assertTrue(c.commands().contains(MotionCommand.of(ArCommands.HEAD, 60)), c.toString());
  }

  @Test
  void aStopMakesZeroTheLastValueSent() {
    ReflectionMemory stopped = CONNECTED.stopped(100 * MS);
    DirectMotion zero = vel(0, 100).withRot(RotType.VEL, 0, 100 * MS);
    CycleCommands c = cycle(200, zero, NO_DESIRE, stopped);
    assertFalse(c.commands().contains(MotionCommand.of(ArCommands.VEL, 0)), c.toString());
    assertFalse(c.commands().contains(MotionCommand.of(ArCommands.RVEL, 0)), c.toString());
  }

  @Test
  void vel2PacksBothWheelsIntoOneArgument() {
    assertEquals(
        MotionCommand.of(ArCommands.VEL2, 0x05FB), MotionCommand.twoBytes(ArCommands.VEL2, 5, -5));
    assertEquals(5, StateReflection.vel2Byte(100, 20));
    assertEquals(127, StateReflection.vel2Byte(10_000, 20));
  }

  private static MotionCommand last(List<MotionCommand> l) {
    return l.get(l.size() - 1);
  }
}
