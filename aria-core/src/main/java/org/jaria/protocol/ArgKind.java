package org.jaria.protocol;

/** The kind of argument an ARCOS client command takes. */
public enum ArgKind {
  /** No argument: the command ID alone. */
  NONE,
  /** A signed integer: type byte 0x3B (positive) or 0x1B (negative) and the absolute value. */
  INT,
  /** An unsigned integer 0..65535, type byte 0x3B. */
  UINT,
  /** Two bytes packed into one integer (high byte, low byte), type byte 0x3B. */
  TWO_BYTES,
  /** A string: type byte 0x2B, a length byte, then the characters. */
  STRING,
  /** A layout of its own (simulator commands); see the command's documentation. */
  SPECIAL;

  /** Argument type byte for a positive (or unsigned) integer. */
  public static final int INT_ARG = 0x3B;

  /** Argument type byte for a negative integer (the absolute value follows). */
  public static final int NEG_INT_ARG = 0x1B;

  /** Argument type byte for a string. */
  public static final int STR_ARG = 0x2B;
}
