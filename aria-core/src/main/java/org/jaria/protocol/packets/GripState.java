package org.jaria.protocol.packets;

/**
 * The Pioneer gripper's switch byte, as ARIA's {@code ArGripper} decodes it: in a GRIPPERpac, in
 * the SIP's GRIP_STATE byte, and (bits 0–5) on the user digital inputs (DIGIN), where the gripper
 * is wired. Limit and paddle switches are active low: a clear bit means the switch is pressed.
 *
 * <table>
 *   <caption>Bits</caption>
 *   <tr><th>bit</th><th>set</th><th>clear</th></tr>
 *   <tr><td>0</td><td>paddles not fully open</td><td>paddles open (limit switch)</td></tr>
 *   <tr><td>1</td><td>lift between its ends</td><td>lift at the top or bottom</td></tr>
 *   <tr><td>2</td><td>outer break beam broken</td><td>clear</td></tr>
 *   <tr><td>3</td><td>inner break beam broken</td><td>clear</td></tr>
 *   <tr><td>4</td><td>left paddle free</td><td>left paddle touches (closed)</td></tr>
 *   <tr><td>5</td><td>right paddle free</td><td>right paddle touches (closed)</td></tr>
 *   <tr><td>6</td><td>lift moving</td><td>lift still</td></tr>
 *   <tr><td>7</td><td>paddles moving</td><td>paddles still</td></tr>
 * </table>
 *
 * <p>The decoders below are ARIA's, as plain functions of the byte.
 */
public final class GripState {
  /** Set while the paddles are not fully open. */
  public static final int NOT_OPEN = 1;

  /** Set while the lift is between the top and the bottom. */
  public static final int LIFT_BETWEEN = 1 << 1;

  /** The outer break beam is broken. */
  public static final int OUTER_BEAM = 1 << 2;

  /** The inner break beam is broken. */
  public static final int INNER_BEAM = 1 << 3;

  /** Set while the left paddle touches nothing. */
  public static final int LEFT_FREE = 1 << 4;

  /** Set while the right paddle touches nothing. */
  public static final int RIGHT_FREE = 1 << 5;

  /** The lift is moving. */
  public static final int LIFT_MOVING = 1 << 6;

  /** The paddles are moving. */
  public static final int GRIP_MOVING = 1 << 7;

  private GripState() {}

  /** 2 if both paddles touch (closed), else 1 if they are fully open, else 0 (between). */
  public static int gripState(int d) {
    if ((d & LEFT_FREE) == 0 && (d & RIGHT_FREE) == 0) {
      return 2;
    }
    return (d & NOT_OPEN) == 0 ? 1 : 0;
  }

  /** 0 no paddle touches, 1 the left one, 2 the right one, 3 both. */
  public static int paddleState(int d) {
    return ((d & LEFT_FREE) == 0 ? 1 : 0) + ((d & RIGHT_FREE) == 0 ? 2 : 0);
  }

  /** 0 no beam broken, 1 the inner one, 2 the outer one, 3 both. */
  public static int breakBeamState(int d) {
    return ((d & INNER_BEAM) != 0 ? 1 : 0) + ((d & OUTER_BEAM) != 0 ? 2 : 0);
  }

  /** Whether the lift is at the top or the bottom. */
  public static boolean isLiftMaxed(int d) {
    return (d & LIFT_BETWEEN) == 0;
  }
}
