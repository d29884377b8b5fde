package org.jaria.gripper;

import java.util.concurrent.atomic.AtomicLong;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.GripState;
import org.jaria.protocol.packets.GripperPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;

/**
 * A Pioneer gripper: two paddles and a lift (ARIA's {@code ArGripper}). Commands go to the robot as
 * GRIPPER commands; the state comes from the GRIPPERpac the robot is asked to stream on connecting
 * (GRIPREQUEST 2), or from the SIP's GRIP_STATE byte until the first GRIPPERpac arrives. GRIP_STATE
 * bits: paddles open, closed, moving, error; lift up, down, moving, error.
 */
public class ArGripper {

  /** Where the gripper's state comes from (ARIA's gripper types JAria reads). */
  public enum Type {
    /** Not known yet: no GRIPPERpac has arrived. */
    QUERYTYPE,
    /** The robot sends GRIPPERpacs. */
    GRIPPAC,
    /** The robot says it has no gripper. */
    NOGRIPPER
  }

  private final ArRobot robot;
  private final Runnable onConnect = this::requestPackets;
  private volatile Type type = Type.QUERYTYPE;
  private volatile int packetState = -1;
  private volatile int graspTime;
  private final AtomicLong packets = new AtomicLong();

  /** A gripper on {@code robot}; asks for its packets now (if connected) and on every connect. */
  public ArGripper(ArRobot robot) {
    this.robot = robot;
    robot.addPacketHandler(this::handle, ArListPos.FIRST);
    robot.addConnectCB(onConnect);
    if (robot.isConnected()) {
      requestPackets();
    }
  }

  private void requestPackets() {
    robot.comInt(ArCommands.GRIPREQUEST, 2);
  }

  private boolean handle(ArRobotPacket p) {
    if (p.getID() != PacketIds.GRIPPER) {
      return false;
    }
    GripperPacket g = GripperPacket.decode(p);
    if (g == null) {
      return true;
    }
    type = g.hasGripper() == 0 ? Type.NOGRIPPER : Type.GRIPPAC;
    graspTime = g.graspTime();
    packetState = g.gripState();
    packets.incrementAndGet();
    return true;
  }

  private boolean command(int arg) {
    return robot.comInt(ArCommands.GRIPPER, arg);
  }

  /** Opens the paddles. */
  public boolean gripOpen() {
    return command(ArGripperCommands.GRIP_OPEN);
  }

  /** Closes the paddles. */
  public boolean gripClose() {
    return command(ArGripperCommands.GRIP_CLOSE);
  }

  /** Stops the paddles. */
  public boolean gripStop() {
    return command(ArGripperCommands.GRIP_STOP);
  }

  /** Raises the lift. */
  public boolean liftUp() {
    return command(ArGripperCommands.LIFT_UP);
  }

  /** Lowers the lift. */
  public boolean liftDown() {
    return command(ArGripperCommands.LIFT_DOWN);
  }

  /** Stops the lift. */
  public boolean liftStop() {
    return command(ArGripperCommands.LIFT_STOP);
  }

  /** Closes the paddles and raises the lift. */
  public boolean gripperStore() {
    return command(ArGripperCommands.GRIPPER_STORE);
  }

  /** Opens the paddles and lowers the lift. */
  public boolean gripperDeploy() {
    return command(ArGripperCommands.GRIPPER_DEPLOY);
  }

  /** Stops paddles and lift. */
  public boolean gripperHalt() {
    return command(ArGripperCommands.GRIPPER_HALT);
  }

  /** Sets how hard the paddles squeeze (the time, in 20 ms units, they keep pushing). */
  public boolean gripPressure(int mSecIntervals) {
    return robot.comInt(ArCommands.GRIPPERVAL, mSecIntervals)
        && command(ArGripperCommands.GRIP_PRESSURE);
  }

  /** Moves the lift for {@code mSecIntervals} ms (positive up, negative down). */
  public boolean liftCarry(int mSecIntervals) {
    return robot.comInt(ArCommands.GRIPPERVAL, mSecIntervals)
        && command(ArGripperCommands.LIFT_CARRY);
  }

  /** The GRIP_STATE byte: from the last GRIPPERpac, else from the SIP. */
  public int getGripStateByte() {
    int s = packetState;
    return s >= 0 ? s : robot.getGripState();
  }

  /** 1 if the paddles are open, 2 if closed, 0 if between (ARIA's values). */
  public int getGripState() {
    int s = getGripStateByte();
    if ((s & GripState.PADDLES_OPEN) != 0) {
      return 1;
    }
    if ((s & GripState.PADDLES_CLOSED) != 0) {
      return 2;
    }
    return 0;
  }

  /** Whether the paddles are moving. */
  public boolean isGripMoving() {
    return (getGripStateByte() & GripState.PADDLES_MOVING) != 0;
  }

  /** Whether the lift is moving. */
  public boolean isLiftMoving() {
    return (getGripStateByte() & GripState.LIFT_MOVING) != 0;
  }

  /** Whether the lift is all the way up or down. */
  public boolean isLiftMaxed() {
    return (getGripStateByte() & (GripState.LIFT_UP | GripState.LIFT_DOWN)) != 0;
  }

  /** Whether the lift is all the way up. */
  public boolean isLiftUp() {
    return (getGripStateByte() & GripState.LIFT_UP) != 0;
  }

  /** Whether the paddles or the lift report an error. */
  public boolean hasError() {
    return (getGripStateByte() & (GripState.PADDLES_ERROR | GripState.LIFT_ERROR)) != 0;
  }

  /** Where the state comes from. */
  public Type getType() {
    return type;
  }

  /** The grasp time the robot reports. */
  public int getGraspTime() {
    return graspTime;
  }

  /** GRIPPERpacs received. */
  public long getPacketCount() {
    return packets.get();
  }

  /** A one-line description of the state, as ARIA's {@code logState} prints. */
  public String stateString() {
    String paddles =
        switch (getGripState()) {
          case 1 -> "open";
          case 2 -> "closed";
          default -> "between";
        };
    String lift = isLiftMaxed() ? "maxed" : "between";
    return "Grip: "
        + paddles
        + (isGripMoving() ? "_moving" : "")
        + "  Lift: "
        + lift
        + (isLiftMoving() ? "_moving" : "");
  }
}
