package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Motion commands and state reflection, byte by byte against the fake robot. */
class ArRobotMotionTest {

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

  @Test
  void moveIsSentOnceThenPulsedAndDoneWhenTheDistanceIsCovered() {
    rig.robot.move(1000);
    rig.run(100);
    assertEquals(1, sent(ArCommands.MOVE).size());
    assertEquals(1000, sent(ArCommands.MOVE).get(0).intArg());
    assertFalse(rig.robot.isMoveDone());
    rig.sip.setPos(980, 0, 0);
    rig.run(1000);
    assertEquals(1, sent(ArCommands.MOVE).size(), "MOVE is not repeated");
    assertTrue(rig.robot.isMoveDone(), "within 40 mm of 1000");
    assertFalse(rig.robot.isMoveDone(10));
  }

  @Test
  void headingIsConvertedIntoTheRobotsOwnFrame() {
    rig.robot.moveTo(new ArPose(0, 0, 90)); // localization says we face +y
    rig.robot.setHeading(180);
    rig.run(100);
    // the robot's own heading frame is still 0 where the world says 90
    assertEquals(90, sent(ArCommands.HEAD).get(0).intArg());
    assertFalse(rig.robot.isHeadingDone());
    rig.sip.setPos(0, 0, 1024); // odometry 90 degrees = world 180
    rig.run(100);
    assertTrue(rig.robot.isHeadingDone());
  }

  @Test
  void deltaHeadingIsRelativeToTheCurrentHeading() {
    rig.sip.setPos(0, 0, 512); // 45 degrees
    rig.run(100);
    rig.fake.clearReceived();
    rig.robot.setDeltaHeading(-90);
    rig.run(100);
    assertEquals(-45, sent(ArCommands.HEAD).get(0).intArg());
  }

  @Test
  void vel2IsSentInVel2DivisorStepsAsSignedBytes() {
    rig.robot.setVel2(-200, 400);
    rig.run(100);
    int v = sent(ArCommands.VEL2).get(0).intArg();
    assertEquals(-10, (byte) (v >> 8));
    assertEquals(20, (byte) v);
    assertTrue(sent(ArCommands.VEL).isEmpty());
    assertTrue(sent(ArCommands.RVEL).isEmpty());
  }

  @Test
  void stopSendsStopAndHoldsZero() {
    rig.robot.setVel(300);
    rig.robot.setRotVel(20);
    rig.run(100);
    rig.fake.clearReceived();
    rig.robot.stop();
    rig.run(100);
    assertEquals(1, sent(ArCommands.STOP).size());
    assertTrue(sent(ArCommands.VEL).isEmpty(), "zero is already known to be sent");
    rig.run(600);
    assertEquals(0, sent(ArCommands.VEL).get(0).intArg());
  }

  @Test
  void velocityIsClampedToTheMaximum() {
    rig.robot.setVel(5000);
    rig.run(100);
    assertEquals(750, sent(ArCommands.VEL).get(0).intArg());
  }

  /** An action that always wants a velocity. */
  private static final class Want extends ArAction {
    private final ArActionDesired d = new ArActionDesired();
    private final double vel;

    Want(double vel) {
      super("want " + vel);
      this.vel = vel;
    }

    @Override
    public ArActionDesired fire(ArActionDesired current) {
      d.reset();
      d.setVel(vel);
      d.setRotVel(5);
      return d;
    }
  }

  @Test
  void directMotionBeatsActionsUntilClearedOrItsPrecedenceTimeEnds() {
    rig.robot.addAction(new Want(123), 50);
    rig.run(100);
    assertEquals(123, sent(ArCommands.VEL).get(0).intArg());
    rig.robot.setVel(200);
    rig.fake.clearReceived();
    rig.run(1000);
    assertTrue(sent(ArCommands.VEL).stream().allMatch(r -> r.intArg() == 200));
    rig.robot.clearDirectMotion();
    rig.fake.clearReceived();
    rig.run(100);
    assertEquals(123, sent(ArCommands.VEL).get(0).intArg());

    rig.robot.setDirectMotionPrecedenceTime(300);
    rig.robot.setVel(50);
    rig.fake.clearReceived();
    rig.run(200);
    assertEquals(50, sent(ArCommands.VEL).get(0).intArg());
    rig.run(300);
    List<FakeRobot.Received> vels = sent(ArCommands.VEL);
    assertEquals(123, vels.get(vels.size() - 1).intArg(), "actions resume after 300 ms");
  }

  @Test
  void withoutStateReflectionCommandsGoOutOnceWhenCalled() {
    LockstepRig direct = new LockstepRig(false);
    assertTrue(direct.connect());
    direct.fake.clearReceived();
    direct.robot.setVel(100);
    direct.run(2000);
    assertEquals(1, direct.fake.received(ArCommands.VEL).size());
    assertTrue(direct.fake.received(ArCommands.PULSE).size() >= 2, "still kept alive");
  }
}
