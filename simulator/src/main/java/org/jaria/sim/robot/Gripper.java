package org.jaria.sim.robot;

import org.jaria.protocol.packets.GripState;

/**
 * The Pioneer 2-axis gripper: paddles that open and close and a lift that goes up and down, each
 * taking a fixed travel time end to end, reported as the switch byte ARIA's {@code ArGripper}
 * decodes ({@link GripState}: active-low limit and paddle switches, moving bits 6 and 7). Nothing
 * passes between the paddles, so the break beams stay clear. It starts stored (paddles closed, lift
 * up).
 *
 * <p>GRIPPER commands: 1 open, 2 close, 3 stop paddles, 4 lift up, 5 lift down, 6 stop lift, 7
 * store (close and lift), 8 deploy (open and lower), 15 halt both, 16 grasp pressure, 17 lift carry
 * (move the lift for the value ms, + up). The value of 16 and 17 is the GRIPPERVAL sent right after
 * the command (ARIA's order), or else the last one sent before it.
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class Gripper {

  /** Time for the paddles to travel from closed to open, ms. */
  public static final double PADDLE_TRAVEL_MS = 2000;

  /** Time for the lift to travel from bottom to top, ms. */
  public static final double LIFT_TRAVEL_MS = 4000;

  private double paddle;
  private double paddleTarget;
  private double lift = 1;
  private double liftTarget = 1;
  private int graspTime = 10;
  private int gripperVal;
  private int awaitingValueFor;

  /** Returns to the stored position instantly (a fresh robot). */
  public void reset() {
    paddle = 0;
    paddleTarget = 0;
    lift = 1;
    liftTarget = 1;
  }

  /** GRIPPERVAL: the value used by the next pressure or carry command. */
  public void setGripperVal(int v) {
    gripperVal = v;
    if (awaitingValueFor != 0) {
      applyValue(awaitingValueFor);
      awaitingValueFor = 0;
    }
  }

  private void applyValue(int cmd) {
    if (cmd == 16) {
      graspTime = Math.max(0, Math.min(255, gripperVal));
    } else {
      liftTarget = Math.max(0, Math.min(1, lift + gripperVal / LIFT_TRAVEL_MS));
    }
  }

  /** Executes a GRIPPER command; unknown codes are ignored. */
  public void command(int cmd) {
    awaitingValueFor = cmd == 16 || cmd == 17 ? cmd : 0;
    switch (cmd) {
      case 1 -> paddleTarget = 1;
      case 2 -> paddleTarget = 0;
      case 3 -> paddleTarget = paddle;
      case 4 -> liftTarget = 1;
      case 5 -> liftTarget = 0;
      case 6 -> liftTarget = lift;
      case 7 -> {
        paddleTarget = 0;
        liftTarget = 1;
      }
      case 8 -> {
        paddleTarget = 1;
        liftTarget = 0;
      }
      case 15 -> {
        paddleTarget = paddle;
        liftTarget = lift;
      }
      case 16, 17 -> applyValue(cmd);
      default -> {
        // not a gripper command ARCOS knows: ignored, as on the robot
      }
    }
  }

  /** Moves paddles and lift for {@code dtMs}. */
  public void tick(double dtMs) {
    paddle = toward(paddle, paddleTarget, dtMs / PADDLE_TRAVEL_MS);
    lift = toward(lift, liftTarget, dtMs / LIFT_TRAVEL_MS);
  }

  private static double toward(double cur, double target, double step) {
    if (cur < target) {
      return Math.min(target, cur + step);
    }
    return Math.max(target, cur - step);
  }

  /** The switch byte (see {@link GripState}). */
  public int state() {
    int s = 0;
    if (paddle < 1) {
      s |= GripState.NOT_OPEN;
    }
    if (lift > 0 && lift < 1) {
      s |= GripState.LIFT_BETWEEN;
    }
    if (paddle > 0) {
      s |= GripState.LEFT_FREE | GripState.RIGHT_FREE; // closed paddles press both switches
    }
    if (lift != liftTarget) {
      s |= GripState.LIFT_MOVING;
    }
    if (paddle != paddleTarget) {
      s |= GripState.GRIP_MOVING;
    }
    return s;
  }

  /** Grasp pressure/time value. */
  public int graspTime() {
    return graspTime;
  }

  /** Paddle opening, 0 closed .. 1 open. */
  public double paddlePosition() {
    return paddle;
  }

  /** Lift height, 0 bottom .. 1 top. */
  public double liftPosition() {
    return lift;
  }
}
