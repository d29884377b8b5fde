package org.jaria.protocol.packets;

/** Bits of the GRIP_STATE byte (SIP tail and GRIPPERpac). */
public final class GripState {
  /** Paddles fully open. */
  public static final int PADDLES_OPEN = 1;

  /** Paddles closed. */
  public static final int PADDLES_CLOSED = 1 << 1;

  /** Paddles moving. */
  public static final int PADDLES_MOVING = 1 << 2;

  /** Paddles error. */
  public static final int PADDLES_ERROR = 1 << 3;

  /** Lift at the top. */
  public static final int LIFT_UP = 1 << 4;

  /** Lift at the bottom. */
  public static final int LIFT_DOWN = 1 << 5;

  /** Lift moving. */
  public static final int LIFT_MOVING = 1 << 6;

  /** Lift error. */
  public static final int LIFT_ERROR = 1 << 7;

  private GripState() {}
}
