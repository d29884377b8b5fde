package org.jaria.action;

import static org.jaria.action.ActionRig.fire;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.input.ArJoyHandler;
import org.jaria.input.ArKeyHandler;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.JoystickPacket;
import org.jaria.protocol.packets.PacketIds;
import org.junit.jupiter.api.Test;

/** Driving by joystick, keyboard and the robot's own joystick. */
class TeleopActionsTest {

  private final ActionRig ar = new ActionRig();

  @Test
  void joydriveWithoutAJoystickAsksForNothing() {
    ArActionJoydrive j = ar.attach(new ArActionJoydrive());
    assertFalse(j.joystickInited());
    assertNull(fire(j));
  }

  @Test
  void joydriveDrivesWhileTheButtonIsHeld() {
    ArActionJoydrive j = ar.attach(new ArActionJoydrive());
    ArJoyHandler joy = j.getJoyHandler();
    joy.connect(3, 2);
    ArActionDesired d = fire(j);
    assertEquals(0, d.getVel(), 1e-9, "no button: stop");
    assertEquals(0, d.getDeltaHeading(), 1e-9);
    joy.setButton(1, true);
    joy.setAxes(64, 128, 0);
    d = fire(j);
    assertEquals(400, d.getVel(), 1e-9);
    assertEquals(-7.5, d.getDeltaHeading(), 1e-9, "stick right: turn right");
    joy.setButton(1, false);
    j.setStopIfNoButtonPressed(false);
    assertNull(fire(j), "let lower priorities drive");
  }

  @Test
  void joydriveThrottleScalesTheSpeed() {
    ArJoyHandler joy = new ArJoyHandler();
    ArActionJoydrive j = ar.attach(new ArActionJoydrive(joy));
    joy.connect(3, 1);
    joy.setButton(1, true);
    j.setThrottleParams(100, 300);
    joy.setAxes(0, 128, 128);
    assertEquals(300, fire(j).getVel(), 1e-9);
    joy.setAxes(0, 128, -128);
    assertEquals(100, fire(j).getVel(), 1e-9);
    joy.setAxes(0, -64, 0);
    assertEquals(-100, fire(j).getVel(), 1e-9);
  }

  @Test
  void keydriveAccumulatesSpeedAndTurnsPerPress() {
    ArKeyHandler keys = new ArKeyHandler();
    ArActionKeydrive k = ar.attach(new ArActionKeydrive(keys));
    assertSame(ar.robot(), keys.getAttachedRobot(), "attached with ARIA's default keys");
    assertNotNull(ar.robot().findSensorInterpTask(ArKeyHandler.TASK_NAME));
    keys.feedKey(ArKeyHandler.UP);
    keys.feedKey(ArKeyHandler.UP);
    keys.feedKey(ArKeyHandler.LEFT);
    keys.feedKey(ArKeyHandler.LEFT);
    keys.checkKeys();
    ArActionDesired d = fire(k);
    assertEquals(50, d.getVel(), 1e-9);
    assertEquals(16, d.getDeltaHeading(), 1e-9);
    d = fire(k);
    assertEquals(50, d.getVel(), 1e-9, "speed persists");
    assertEquals(0, d.getDeltaHeading(), 1e-9, "turning does not");
    for (int i = 0; i < 4; i++) {
      keys.feedKey(ArKeyHandler.RIGHT);
    }
    keys.checkKeys();
    assertEquals(-24, fire(k).getDeltaHeading(), 1e-9, "at most 24 degrees per cycle");
    keys.feedKey(ArKeyHandler.SPACE);
    keys.checkKeys();
    assertEquals(0, fire(k).getVel(), 1e-9);
    for (int i = 0; i < 20; i++) {
      k.down();
    }
    assertEquals(-400, fire(k).getVel(), 1e-9, "at most 400 mm/s");
  }

  @Test
  void keydriveRespectsLimitsFromHigherPriorities() {
    ArActionKeydrive k = ar.attach(new ArActionKeydrive(new ArKeyHandler()));
    for (int i = 0; i < 12; i++) {
      k.up();
    }
    assertEquals(300, fire(k).getVel(), 1e-9);
    ArActionDesired limited = new ArActionDesired();
    limited.setMaxVel(100);
    assertEquals(100, k.fire(limited).getVel(), 1e-9, "the speed kept is cut to the limit");
  }

  @Test
  void keydriveGivesUpItsKeysWhenDeactivated() {
    ArKeyHandler keys = new ArKeyHandler();
    ArActionKeydrive k = ar.attach(new ArActionKeydrive(keys));
    assertNotNull(keys.getKeyHandler(ArKeyHandler.UP));
    k.deactivate();
    assertNull(keys.getKeyHandler(ArKeyHandler.UP));
    assertNull(keys.getKeyHandler(ArKeyHandler.SPACE));
    k.activate();
    assertNotNull(keys.getKeyHandler(ArKeyHandler.DOWN));
  }

  @Test
  void keydriveThroughTheRobotsCycle() {
    ArKeyHandler keys = new ArKeyHandler();
    ArActionKeydrive k = new ArActionKeydrive(keys);
    ar.robot().addAction(k, 45);
    keys.feedKey(ArKeyHandler.UP);
    ar.run(100);
    assertEquals(25, ar.robot().getActionDesired().getVel(), 1e-9);
  }

  @Test
  void robotJoydriveAsksForJoystickPacketsAndDrivesWithTheDeadman() {
    ar.rig.fake.clearReceived();
    ArActionRobotJoydrive j = ar.attach(new ArActionRobotJoydrive());
    ar.run(100);
    assertTrue(
        ar.rig.fake.received(ArCommands.JOYINFO).stream().anyMatch(x -> x.intArg() == 2),
        "JOYINFO 2 sent");
    assertNull(fire(j), "no deadman");
    ar.send(new JoystickPacket(1, 0, 512, 512, 1024).encode(new ArRobotPacket()));
    assertEquals(1, j.getPacketsReceived());
    ArActionDesired d = fire(j);
    assertEquals(0, d.getVel(), 1e-9, "centred: stop");
    assertNotNull(fire(j), "still holding the robot while the deadman is pressed");
    ar.send(new JoystickPacket(1, 0, 0, 1023, 1024).encode(new ArRobotPacket()));
    d = fire(j);
    double vmax = ar.robot().getTransVelMax();
    double rmax = ar.robot().getRotVelMax();
    assertEquals(511 / 512.0 * vmax, d.getVel(), 1e-6);
    assertEquals(rmax, d.getRotVel(), 1e-6, "stick left: turn left");
  }

  @Test
  void robotJoydriveWithoutDeadmanYieldsWhenCentred() {
    ArActionRobotJoydrive j = ar.attach(new ArActionRobotJoydrive("rj", false));
    assertNotNull(fire(j), "centred: stop once");
    assertNull(fire(j), "then let others drive");
    ar.vel(200);
    ar.send(new JoystickPacket(0, 0, 512, 0, 1024).encode(new ArRobotPacket()));
    ArActionDesired d = fire(j);
    assertEquals(ar.robot().getTransDecel() * 3, d.getTransDecel(), 1e-9, "braking harder");
    assertTrue(d.getVel() < 0);
  }

  @Test
  void robotJoydriveAddedTwiceListensOnce() {
    ar.rig.fake.clearReceived();
    ArActionRobotJoydrive j = new ArActionRobotJoydrive();
    ar.robot().addAction(j, 10);
    ar.robot().addAction(j, 20);
    ar.run(100);
    assertEquals(1, ar.rig.fake.received(ArCommands.JOYINFO).size());
    ar.send(new JoystickPacket(1, 0, 512, 512, 0).encode(new ArRobotPacket()));
    assertEquals(1, j.getPacketsReceived());
  }

  @Test
  void robotJoydriveIgnoresAShortPacket() {
    ArActionRobotJoydrive j = ar.attach(new ArActionRobotJoydrive());
    ArRobotPacket p = new ArRobotPacket();
    p.empty().setID(PacketIds.JOYSTICK).uByteToBuf(1).finalizePacket();
    ar.send(p);
    assertEquals(0, j.getPacketsReceived());
    assertEquals(0, j.getLastJoystickPacket().button1());
    assertTrue(ar.robot().isConnected());
  }

  @Test
  void ratioDriveGroupTakesKeysAndDrivesThroughTheRatioAction() {
    ArKeyHandler keys = new ArKeyHandler();
    ArJoyHandler joy = new ArJoyHandler();
    ArActionGroupRatioDrive g = new ArActionGroupRatioDrive(ar.robot(), keys, joy);
    assertEquals(3, g.getActionList().size());
    g.activateExclusive();
    ar.run(100);
    assertNotNull(keys.getKeyHandler(ArKeyHandler.UP), "keys taken at the first fire");
    for (int i = 0; i < 4; i++) {
      keys.feedKey(ArKeyHandler.UP);
    }
    ar.run(200);
    double vmax = ar.robot().getTransVelMax();
    assertEquals(0.2 * vmax, ar.robot().getActionDesired().getVel(), 1e-6);
    keys.feedKey(ArKeyHandler.LEFT);
    ar.run(100);
    assertEquals(50, ar.robot().getActionDesired().getRotVel(), 1e-6, "full left at low speed");
    ar.run(100);
    assertEquals(0, ar.robot().getActionDesired().getRotVel(), 1e-9, "one press, one cycle");

    joy.connect(2, 1);
    joy.setButton(1, true);
    joy.setAxes(0, 64, 0);
    ar.run(100);
    assertEquals(0.5 * vmax, ar.robot().getActionDesired().getVel(), 1e-6, "joystick overrides");
    joy.setButton(1, false);
    ar.run(100);
    assertEquals(0, ar.robot().getActionDesired().getVel(), 1e-9, "released: stop once");

    g.deactivate();
    assertNull(keys.getKeyHandler(ArKeyHandler.UP), "keys given up while inactive");
  }

  @Test
  void ratioInputFromTheRobotsJoystickNeedsTheDeadman() {
    ArActionRatioInput in = ar.attach(new ArActionRatioInput());
    ArRatioInputRobotJoydrive rj = new ArRatioInputRobotJoydrive(ar.robot(), in);
    ar.send(new JoystickPacket(0, 0, 512, 1023, 1024).encode(new ArRobotPacket()));
    fire(in);
    assertEquals(0, in.getTransRatio(), 1e-9, "no deadman");
    ar.send(new JoystickPacket(1, 0, 256, 1023, 512).encode(new ArRobotPacket()));
    fire(in);
    assertEquals(511 / 512.0 * 100, in.getTransRatio(), 1e-6);
    assertEquals(50, in.getRotRatio(), 1e-6, "stick half left");
    assertEquals(50, in.getThrottleRatio(), 1e-6);
    assertEquals(2, rj.getRobotJoyHandler().getPacketsReceived());
  }
}
