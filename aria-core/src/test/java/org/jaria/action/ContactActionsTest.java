package org.jaria.action;

import static org.jaria.action.ActionRig.fire;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.IoPacket;
import org.junit.jupiter.api.Test;

/** Bumpers, stalls, IRs and table sensors. */
class ContactActionsTest {

  private static ArRobotPacket io(int digIn3) {
    return new IoPacket(new int[] {0, 0, 0, digIn3}, new int[0], new int[0])
        .encode(new ArRobotPacket());
  }

  @Test
  void bumpersBackOffThenTurnAwayFromTheMiddleBumper() {
    ActionRig ar = new ActionRig("peoplebot-sh");
    ArActionBumpers b = ar.attach(new ArActionBumpers());
    ar.vel(100);
    assertNull(fire(b), "no bump");
    ar.stallAndBumpers(1 << (9 + 2)); // front bumper 2 of 5, the middle one
    ArActionDesired d = fire(b);
    assertNotNull(d);
    assertEquals(-100, d.getVel(), 1e-9);
    assertTrue(d.isHeadingSet());
    assertEquals(67.5, d.getHeading(), 1e-9);
    d = fire(b);
    assertEquals(-100, d.getVel(), 1e-9, "backing off");
    assertEquals(0, d.getDeltaHeading(), 1e-9);
    ar.stallAndBumpers(0).run(3000);
    d = fire(b);
    assertEquals(0, d.getVel(), 1e-9, "then turning in place");
    assertEquals(67.5, d.getHeading(), 1e-9);
    ar.pose(0, 0, 67.5);
    assertNull(fire(b), "done once turned");
  }

  @Test
  void bumpersTurnLessForSideBumpersAndDriveForwardFromRearBumps() {
    ActionRig ar = new ActionRig("peoplebot-sh");
    ArActionBumpers b = ar.attach(new ArActionBumpers());
    assertEquals(-13.5, b.findDegreesToTurn(0b1, 1), 1e-9, "leftmost bumper: a little right");
    assertEquals(13.5, b.findDegreesToTurn(0b10000, 1), 1e-9);
    assertEquals(0, b.findDegreesToTurn(0b1000000, 1), 1e-9, "no such bumper: no turn");
    ar.vel(-100).stallAndBumpers(1 << (1 + 2)); // rear bumper 2
    ArActionDesired d = fire(b);
    assertEquals(100, d.getVel(), 1e-9);
    assertEquals(-67.5, d.getHeading(), 1e-9);
  }

  @Test
  void bumpersNeedBumpersInTheParameters() {
    ActionRig ar = new ActionRig();
    ArActionBumpers b = ar.attach(new ArActionBumpers("b", 100, 3000, 3000, true));
    ar.vel(100).stallAndBumpers(1 << 11);
    assertNull(fire(b), "a P3-DX's parameters declare no bumpers");
  }

  @Test
  void bumpersCanLimitTheBackOffSpeed() {
    ActionRig ar = new ActionRig("peoplebot-sh");
    ArActionBumpers b = ar.attach(new ArActionBumpers("b", 150, 3000, 3000, true));
    ar.vel(100).stallAndBumpers(1 << 9);
    ArActionDesired d = fire(b);
    assertEquals(-150, d.getMaxNegVel(), 1e-9);
  }

  @Test
  void stallRecoverBacksAndTurnsAwayFromTheStalledWheel() {
    ActionRig ar = new ActionRig();
    ArActionStallRecover s = ar.attach(new ArActionStallRecover());
    assertNull(fire(s));
    ar.stallAndBumpers(0x1); // left motor
    ArActionDesired d = fire(s);
    assertTrue(s.isRecovering());
    assertEquals(-150, d.getVel(), 1e-9);
    assertTrue(d.isHeadingSet());
    assertEquals(-45, d.getHeading(), 1e-9, "away from the stalled left wheel");
    ar.stallAndBumpers(0);
    for (int i = 0; i < 60 && s.isRecovering(); i++) {
      fire(s);
    }
    assertFalse(s.isRecovering(), "the manoeuvre ends after its cycles");
  }

  @Test
  void stallRecoverTriesTheNextManoeuvreForAQuickSecondStall() {
    ActionRig ar = new ActionRig();
    ArActionStallRecover s = ar.attach(new ArActionStallRecover());
    ar.stallAndBumpers(0x100); // right motor
    assertEquals(45, fire(s).getHeading(), 1e-9);
    ArActionDesired full = new ArActionDesired();
    full.setVel(0);
    assertNull(s.fire(full), "a higher priority took the wheels");
    assertFalse(s.isRecovering());
    ArActionDesired d = fire(s);
    assertEquals(150, d.getVel(), 1e-9, "second try: forward and turn");
    ar.run(6000);
    s.fire(full);
    assertEquals(-150, fire(s).getVel(), 1e-9, "after 5 s the sequence starts over");
  }

  @Test
  void stallRecoverCanBeDisabled() {
    ActionRig ar = new ActionRig();
    ArActionStallRecover s = ar.attach(new ArActionStallRecover());
    s.setEnabled(false);
    ar.stallAndBumpers(0x101);
    assertNull(fire(s));
  }

  @Test
  void irsBackAwayAfterTheirCycles() {
    ActionRig ar = new ActionRig("peoplebot-sh");
    ArActionIRs irs = ar.attach(new ArActionIRs());
    ar.send(io(0xFF)).vel(100);
    assertNull(fire(irs), "nothing seen");
    ar.send(io(0xFE)); // IR 0 (front right) sees something
    assertNull(fire(irs), "first cycle of two");
    ar.rig.fake.clearReceived();
    ArActionDesired d = fire(irs);
    assertNotNull(d);
    assertEquals(-100, d.getVel(), 1e-9);
    double angle = Math.toDegrees(Math.atan2(-233, 333));
    assertEquals(-(67.5 + angle), d.getHeading(), 1e-9);
    ar.run(100);
    assertFalse(ar.rig.fake.received(ArCommands.E_STOP).isEmpty());
    assertEquals(-100, fire(irs).getVel(), 1e-9, "backing off for 5 s");
  }

  @Test
  void irsDoNothingOnRobotsWithout() {
    ActionRig ar = new ActionRig();
    ArActionIRs irs = ar.attach(new ArActionIRs());
    ar.vel(100);
    assertNull(fire(irs));
  }

  @Test
  void tableSensorLimiterStopsWhenATableIrTriggers() {
    ActionRig ar = new ActionRig("peoplebot-sh");
    ArActionLimiterTableSensor t = ar.attach(new ArActionLimiterTableSensor());
    ar.send(io(0xFF));
    assertNull(fire(t));
    ar.send(io(0xFD)); // left table IR
    assertEquals(0, fire(t).getMaxVel(), 1e-9);
    ActionRig p3 = new ActionRig();
    assertNull(fire(p3.attach(new ArActionLimiterTableSensor())), "no table IRs on a P3-DX");
  }

  @Test
  void avoidFrontTurnsAwayFromATriggeredTableIr() {
    ActionRig ar = new ActionRig("peoplebot-sh");
    ArActionAvoidFront a = ar.attach(new ArActionAvoidFront());
    ar.send(io(0xFF));
    assertNull(fire(a));
    ar.send(io(0xFE)); // right table IR
    ArActionDesired d = fire(a);
    assertEquals(-15, d.getDeltaHeading(), 1e-9);
    assertEquals(0, d.getVel(), 1e-9);
    ArActionAvoidFront noIr = ar.attach(new ArActionAvoidFront("no ir", 450, 200, 15, false));
    assertNull(fire(noIr));
  }
}
