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

/** ArGripper driving the simulator's gripper over ARCOS packets, on virtual time. */
class ArGripperSimTest {

  private static final Duration LIMIT = Duration.ofSeconds(20);

  @Test
  void opensClosesLiftsStoresAndDeploysAsTheSimulatorReports() {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot simRobot = world.addRobot(RobotOptions.of("p3dx-sh").withGripper(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot)) {
        ArGripper g = new ArGripper(sim.robot());
        assertTrue(sim.runUntil(() -> g.getPacketCount() > 0, LIMIT), "GRIPPERpacs stream");
        assertEquals(ArGripper.Type.GRIPPAC, g.getType());

        assertTrue(g.gripOpen());
        assertTrue(sim.runUntil(g::isGripMoving, LIMIT), "the paddles start moving");
        assertTrue(sim.runUntil(() -> g.getGripState() == 1 && !g.isGripMoving(), LIMIT));
        assertTrue((simRobot.getGripState() & GripState.PADDLES_OPEN) != 0, "the simulator agrees");

        assertTrue(g.liftDown());
        assertTrue(
            sim.runUntil(() -> g.isLiftMaxed() && !g.isLiftMoving() && !g.isLiftUp(), LIMIT));

        assertTrue(g.gripperStore());
        assertTrue(
            sim.runUntil(() -> g.getGripState() == 2 && g.isLiftUp() && !g.isLiftMoving(), LIMIT),
            g.stateString());
        assertEquals("Grip: closed  Lift: maxed", g.stateString());

        assertTrue(g.gripperDeploy());
        assertTrue(
            sim.runUntil(
                () ->
                    g.getGripState() == 1 && g.isLiftMaxed() && !g.isLiftUp() && !g.isLiftMoving(),
                LIMIT),
            g.stateString());

        assertTrue(g.gripPressure(77));
        assertTrue(sim.runUntil(() -> g.getGraspTime() == 77, LIMIT), "GRIPPERVAL then GRIPPER 16");
        assertFalse(g.hasError());
      }
    }
  }

  @Test
  void aRobotWithoutAGripperSaysSo() {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot simRobot = world.addRobot(RobotOptions.of("p3dx-sh").withGripper(false));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot)) {
        ArGripper g = new ArGripper(sim.robot());
        sim.runMillis(2000);
        assertTrue(
            g.getType() == ArGripper.Type.NOGRIPPER || g.getType() == ArGripper.Type.QUERYTYPE,
            "no GRIPPAC type without a gripper: " + g.getType());
        assertEquals(0, g.getGripState());
      }
    }
  }
}
