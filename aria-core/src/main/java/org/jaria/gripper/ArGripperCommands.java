package org.jaria.gripper;

/** Arguments of the GRIPPER command (ARIA's {@code ArGripperCommands}). */
public final class ArGripperCommands {

  private ArGripperCommands() {}

  /** Open the paddles. */
  public static final int GRIP_OPEN = 1;

  /** Close the paddles. */
  public static final int GRIP_CLOSE = 2;

  /** Stop the paddles. */
  public static final int GRIP_STOP = 3;

  /** Raise the lift. */
  public static final int LIFT_UP = 4;

  /** Lower the lift. */
  public static final int LIFT_DOWN = 5;

  /** Stop the lift. */
  public static final int LIFT_STOP = 6;

  /** Close the paddles and raise the lift (carry position). */
  public static final int GRIPPER_STORE = 7;

  /** Open the paddles and lower the lift (ready to pick up). */
  public static final int GRIPPER_DEPLOY = 8;

  /** Stop paddles and lift. */
  public static final int GRIPPER_HALT = 15;

  /** Set the grasp pressure from GRIPPERVAL. */
  public static final int GRIP_PRESSURE = 16;

  /** Move the lift for GRIPPERVAL ms (positive up). */
  public static final int LIFT_CARRY = 17;
}
