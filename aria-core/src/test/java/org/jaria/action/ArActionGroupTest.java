package org.jaria.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.action.ArResolver.PrioritizedAction;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;
import org.junit.jupiter.api.Test;

/** Action groups and ARIA's predefined groups. */
class ArActionGroupTest {

  private final ActionRig ar = new ActionRig();
  private final ArRobot robot = ar.robot();

  private int priorityOf(String name) {
    for (PrioritizedAction p : robot.getActionList()) {
      if (p.action().getName().equals(name)) {
        return p.priority();
      }
    }
    return Integer.MIN_VALUE;
  }

  @Test
  void aGroupAddsItsActionsToTheRobotAndSwitchesThemTogether() {
    ArActionGroup g = new ArActionGroup(robot);
    ArActionStop s = new ArActionStop("s");
    ArActionConstantVelocity c = new ArActionConstantVelocity("c", 100);
    g.addAction(s, 60);
    g.addAction(c, 40);
    ArActionInput other = new ArActionInput("other");
    robot.addAction(other, 10);
    assertSame(s, robot.findAction("s"));
    assertEquals(60, priorityOf("s"));
    assertEquals(List.of(s, c), g.getActionList());
    g.deactivate();
    assertFalse(s.isActive());
    assertFalse(c.isActive());
    assertTrue(other.isActive(), "deactivate leaves the robot's other actions alone");
    g.activate();
    assertTrue(s.isActive() && c.isActive());
    g.activateExclusive();
    assertFalse(other.isActive(), "exclusive: every other action is off");
    assertTrue(s.isActive() && c.isActive());
    g.remAction(c);
    assertNull(robot.findAction("c"));
    g.removeActions();
    assertNull(robot.findAction("s"));
    assertSame(other, robot.findAction("other"));
  }

  @Test
  void wanderHasARIAsActionsAndPriorities() {
    ArActionGroupWander w = new ArActionGroupWander(robot);
    assertEquals(4, w.getActionList().size());
    assertEquals(100, priorityOf("bumpers"));
    assertEquals(90, priorityOf("stall recover"));
    assertEquals(79, priorityOf("Avoid Front"));
    assertEquals(50, priorityOf("Constant Velocity"));
    ArActionAvoidFront af = (ArActionAvoidFront) robot.findAction("Avoid Front");
    assertEquals(450, af.getObstacleDistance());
    assertEquals(200, af.getAvoidVelocity());
    assertEquals(15, af.getTurnAmount());
    assertEquals(
        400, ((ArActionConstantVelocity) robot.findAction("Constant Velocity")).getVelocity());
  }

  @Test
  void wanderDrivesAndStopGroupStops() {
    ArActionGroupWander wander = new ArActionGroupWander(robot, 300, 450, 200, 15);
    ArActionGroupStop stop = new ArActionGroupStop(robot);
    assertEquals(100, priorityOf("stop"));
    wander.activateExclusive();
    ar.run(200);
    assertEquals(300, robot.getActionDesired().getVel(), 1e-9);
    stop.activateExclusive();
    ar.run(200);
    assertEquals(0, robot.getActionDesired().getVel(), 1e-9);
    assertFalse(robot.findAction("Constant Velocity").isActive());
    assertTrue(stop.getActionStop().isActive());
  }

  @Test
  void inputGroupDrivesBehindLimiters() {
    ArActionGroupInput in = new ArActionGroupInput(robot);
    assertEquals(100, priorityOf("TableSensorLimiter"));
    assertEquals(90, priorityOf("Speed Limiter Near"));
    assertEquals(89, priorityOf("Speed Limiter Far"));
    assertEquals(80, priorityOf("speed limiter"));
    assertEquals(70, priorityOf("Input"));
    in.setVel(300);
    ar.run(200);
    assertEquals(300, robot.getActionDesired().getVel(), 1e-9);
    ar.sonar(3, 200);
    assertEquals(0, robot.getActionDesired().getMaxVel(), 1e-9, "obstacle ahead: no forward");
    in.clear();
    assertNotNull(in.getActionInput());
  }

  @Test
  void teleopGroupsReadTheKeyboard() {
    ArKeyHandler keys = new ArKeyHandler();
    ArActionGroupTeleop t = new ArActionGroupTeleop(robot, keys);
    assertEquals(6, t.getActionList().size());
    assertEquals(70, priorityOf("joydrive"));
    assertEquals(69, priorityOf("keydrive"));
    assertFalse(t.getJoydrive().getStopIfNoButtonPressed());
    t.activateExclusive();
    keys.feedKey(ArKeyHandler.UP);
    ar.run(100);
    assertEquals(25, robot.getActionDesired().getVel(), 1e-9);
    t.deactivate();
    robot.remAction(t.getKeydrive());
    ArActionGroupUnguardedTeleop u = new ArActionGroupUnguardedTeleop(robot, keys);
    assertEquals(2, u.getActionList().size());
    assertNotNull(keys.getKeyHandler(ArKeyHandler.UP), "the new keydrive took the keys");
  }
}
