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
 * GRIPPER commands. The state is the gripper's switch byte (see {@link GripState}), read where ARIA
 * reads it for the gripper's {@link Type}:
 *
 * <ul>
 *   <li>{@link Type#QUERYTYPE} (the default) asks the robot for one GRIPPERpac (GRIPREQUEST 2) on
 *       connecting; its first byte says how the gripper is wired: 1 (Pioneer gripper) becomes
 *       {@link Type#USERIO}, 2 {@link Type#GENIO}, anything else {@link Type#NOGRIPPER}; then the
 *       packets are stopped (GRIPREQUEST 0);
 *   <li>{@link Type#USERIO}: switches from the user digital inputs (DIGIN), the moving bits (2 for
 *       the paddles, 6 for the lift) from the SIP byte after GRIP_STATE ({@link
 *       ArRobot#getAnalogPortSelected()}), as ARIA reads the high byte of its two-byte field;
 *   <li>{@link Type#GENIO}: everything from that SIP byte;
 *   <li>{@link Type#GRIPPAC}: everything from the streamed GRIPPERpacs.
 * </ul>
 */
public class ArGripper {

  /** How the gripper's state reaches the client (ARIA's gripper types). */
  public enum Type {
    /** Ask the robot with a GRIPPERpac, then use what it says. */
    QUERYTYPE,
    /** General I/O: the SIP byte after GRIP_STATE. */
    GENIO,
    /** User I/O: the digital inputs. */
    USERIO,
    /** Streamed GRIPPERpacs. */
    GRIPPAC,
    /** No gripper. */
    NOGRIPPER;

    /** The type a GRIPPERpac's first byte stands for: 1 user I/O, 2 general I/O, else none. */
    public static Type fromQuery(int hasGripper) {
      return switch (hasGripper) {
        case 1 -> USERIO;
        case 2 -> GENIO;
        default -> NOGRIPPER;
      };
    }
  }

  private final ArRobot robot;
  private final Runnable onConnect = this::connectHandler;
  private volatile Type type;
  private volatile int switches;
  private volatile int graspTime;
  private final AtomicLong packets = new AtomicLong();

  /** A gripper on {@code robot} whose type is asked of the robot. */
  public ArGripper(ArRobot robot) {
    this(robot, Type.QUERYTYPE);
  }

  /** A gripper on {@code robot} of {@code type}; asks for packets now (if connected) and later. */
  public ArGripper(ArRobot robot, Type type) {
    this.robot = robot;
    this.type = type;
    robot.addPacketHandler(this::handle, ArListPos.FIRST);
    robot.addConnectCB(onConnect);
    if (robot.isConnected()) {
      connectHandler();
    }
  }

  private void connectHandler() {
    if (type == Type.GRIPPAC || type == Type.QUERYTYPE) {
      robot.comInt(ArCommands.GRIPREQUEST, 2);
    }
  }

  private boolean handle(ArRobotPacket p) {
    if (p.getID() != PacketIds.GRIPPER) {
      return false;
    }
    GripperPacket g = GripperPacket.decode(p);
    if (g == null) {
      return true;
    }
    switches = g.gripState();
    graspTime = g.graspTime();
    packets.incrementAndGet();
    if (type == Type.QUERYTYPE) {
      type = Type.fromQuery(g.hasGripper());
      robot.comInt(ArCommands.GRIPREQUEST, 0);
    } else if (type != Type.GRIPPAC) {
      robot.comInt(ArCommands.GRIPREQUEST, 0); // a packet after the stop was asked for
    }
    return true;
  }

  /** Changes the type; GRIPPAC and QUERYTYPE ask for packets again. */
  public void setType(Type t) {
    type = t;
    connectHandler();
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

  /** Sets how long the paddles keep squeezing after both touch, in 20 ms units. */
  public boolean gripPressure(int mSecIntervals) {
    return command(ArGripperCommands.GRIP_PRESSURE)
        && robot.comInt(ArCommands.GRIPPERVAL, mSecIntervals);
  }

  /** Moves the lift for {@code mSecIntervals} ms (positive up, negative down). */
  public boolean liftCarry(int mSecIntervals) {
    return command(ArGripperCommands.LIFT_CARRY)
        && robot.comInt(ArCommands.GRIPPERVAL, mSecIntervals);
  }

  private boolean known() {
    Type t = type;
    return t == Type.GENIO || t == Type.USERIO || t == Type.GRIPPAC;
  }

  /** The byte the switches are read from for this type (paddles, beams, lift limits). */
  private int switchByte() {
    return switch (type) {
      case GENIO -> robot.getAnalogPortSelected();
      case USERIO -> robot.getDigIn();
      default -> switches;
    };
  }

  /** The byte the moving bits are read from for this type. */
  private int movingByte() {
    return type == Type.GRIPPAC ? switches : robot.getAnalogPortSelected();
  }

  /** The switch byte as this gripper's type reads it (0 while the type is not known). */
  public int getSwitches() {
    return known() ? switchByte() : 0;
  }

  /** Whether the paddles are moving (USERIO: bit 2 of the SIP byte, else bit 7). */
  public boolean isGripMoving() {
    if (!known()) {
      return false;
    }
    int bit = type == Type.USERIO ? GripState.OUTER_BEAM : GripState.GRIP_MOVING;
    return (movingByte() & bit) != 0;
  }

  /** Whether the lift is moving. */
  public boolean isLiftMoving() {
    return known() && (movingByte() & GripState.LIFT_MOVING) != 0;
  }

  /** 0 no paddle touches, 1 the left, 2 the right, 3 both. */
  public int getPaddleState() {
    return known() ? GripState.paddleState(switchByte()) : 0;
  }

  /** 1 if the paddles are open, 2 if closed, 0 if between (ARIA's values). */
  public int getGripState() {
    return known() ? GripState.gripState(switchByte()) : 0;
  }

  /** 0 no break beam broken, 1 the inner, 2 the outer, 3 both. */
  public int getBreakBeamState() {
    return known() ? GripState.breakBeamState(switchByte()) : 0;
  }

  /** Whether the lift is all the way up or down. */
  public boolean isLiftMaxed() {
    return known() && GripState.isLiftMaxed(switchByte());
  }

  /** How the state is read. */
  public Type getType() {
    return type;
  }

  /** The grasp time from the last GRIPPERpac, 20 ms units. */
  public int getGraspTime() {
    return graspTime;
  }

  /** GRIPPERpacs received. */
  public long getPacketCount() {
    return packets.get();
  }

  /** A one-line description of the state in the layout of ARIA's {@code logState}. */
  public String stateString() {
    Type t = type;
    if (t == Type.NOGRIPPER) {
      return "There is no gripper.";
    }
    if (t == Type.QUERYTYPE) {
      return "Querying gripper type.";
    }
    String lift = (isLiftMaxed() ? "maxed" : "between") + (isLiftMoving() ? "_moving" : "");
    String grip =
        switch (getGripState()) {
              case 1 -> "open";
              case 2 -> "closed";
              default -> "between";
            }
            + (isGripMoving() ? "_moving" : "");
    String beam =
        switch (getBreakBeamState()) {
          case 1 -> "inner";
          case 2 -> "outter"; // ARIA's spelling, so logs compare equal
          case 3 -> "both";
          default -> "none";
        };
    return String.format("Lift: %15s  Grip: %15s  BreakBeam: %10s", lift, grip, beam);
  }
}
