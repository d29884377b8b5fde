package org.jaria.sim.accessories;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.gripper.ArGripper;
import org.jaria.protocol.packets.GripState;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

/** ArGripper driving the simulator's gripper over ARCOS packets, on virtual time, as ARIA does. */
class ArGripperSimTest {

  private static final Duration LIMIT = Duration.ofSeconds(20);

  private static SimWorld world() {
    return SimWorld.empty(SimOptions.builder().watchdogMillis(0).build());
  }

  @Test
  void theQueriedTypeIsUserIoAndTheStateComesFromTheDigitalInputs() {
    try (SimWorld world = world()) {
      SimRobot simRobot = world.addRobot(RobotOptions.of("p3dx-sh").withGripper(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot)) {
        ArGripper g = new ArGripper(sim.robot());
        assertTrue(sim.runUntil(() -> g.getType() != ArGripper.Type.QUERYTYPE, LIMIT));
        assertEquals(ArGripper.Type.USERIO, g.getType(), "GRIPPERpac type 1: a Pioneer gripper");
        sim.runMillis(1000);
        assertEquals(1, g.getPacketCount(), "one answer, then GRIPREQUEST 0 stops them");
        assertEquals(2, g.getGripState(), "starts stored: closed");
        assertTrue(g.isLiftMaxed());
        assertEquals(3, g.getPaddleState());

        assertTrue(g.gripOpen());
        assertTrue(sim.runUntil(() -> g.getGripState() == 0, LIMIT), "leaves closed");
        assertTrue(sim.runUntil(() -> g.getGripState() == 1, LIMIT), "then open");
        assertEquals(0, g.getPaddleState());

        assertTrue(g.liftDown());
        assertTrue(sim.runUntil(() -> !g.isLiftMaxed(), LIMIT), "between");
        assertTrue(sim.runUntil(g::isLiftMaxed, LIMIT), "at the bottom");

        assertTrue(g.gripperStore());
        assertTrue(
            sim.runUntil(() -> g.getGripState() == 2 && g.isLiftMaxed(), LIMIT), g.stateString());
        assertEquals(
            "Lift:           maxed  Grip:          closed  BreakBeam:       none", g.stateString());
        assertEquals(0, g.getBreakBeamState());
        // ARIA reads a user-I/O gripper's moving bits from the byte after GRIP_STATE: the selected
        // analog port, 0 here, so it never sees them move
        assertFalse(g.isGripMoving());
      }
    }
  }

  @Test
  void asGrippacTheStreamedPacketsShowMotionAndTheGraspTime() {
    try (SimWorld world = world()) {
      SimRobot simRobot = world.addRobot(RobotOptions.of("p3dx-sh").withGripper(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot)) {
        ArGripper g = new ArGripper(sim.robot(), ArGripper.Type.GRIPPAC);
        assertTrue(sim.runUntil(() -> g.getPacketCount() > 3, LIMIT), "GRIPPERpacs stream");
        assertEquals(ArGripper.Type.GRIPPAC, g.getType());

        assertTrue(g.gripperDeploy());
        assertTrue(sim.runUntil(() -> g.isGripMoving() && g.isLiftMoving(), LIMIT));
        assertTrue(
            sim.runUntil(
                () -> g.getGripState() == 1 && g.isLiftMaxed() && !g.isLiftMoving(), LIMIT),
            g.stateString());
        assertEquals(simRobot.getGripState(), g.getSwitches(), "the simulator agrees");
        assertEquals(GripState.LEFT_FREE | GripState.RIGHT_FREE, g.getSwitches());

        assertTrue(g.gripPressure(77)); // GRIPPER 16, then GRIPPERVAL 77, in ARIA's order
        assertTrue(sim.runUntil(() -> g.getGraspTime() == 77, LIMIT), g.stateString());
      }
    }
  }

  @Test
  void aRobotWithoutAGripperSaysSo() {
    try (SimWorld world = world()) {
      SimRobot simRobot = world.addRobot(RobotOptions.of("p3dx-sh").withGripper(false));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot)) {
        ArGripper g = new ArGripper(sim.robot());
        assertTrue(sim.runUntil(() -> g.getType() == ArGripper.Type.NOGRIPPER, LIMIT));
        assertEquals(0, g.getGripState());
        assertEquals("There is no gripper.", g.stateString());
      }
    }
  }
}
