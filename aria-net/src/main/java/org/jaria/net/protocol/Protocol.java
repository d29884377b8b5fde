package org.jaria.net.protocol;

/** Constants of the JAria network protocol (see {@code aria-net/PROTOCOL.md}). */
public final class Protocol {

  private Protocol() {}

  /** The first value of HELLO and CHALLENGE: tells a JAria peer from anything else on the port. */
  public static final String MAGIC = "JARIA-NET";

  /** The protocol version this library speaks. */
  public static final int VERSION = 1;

  /** ArNetworking's default server port. */
  public static final int DEFAULT_PORT = 7272;

  /** Bytes of the length prefix of every frame. */
  public static final int LENGTH_BYTES = 4;

  /** Largest payload part the server puts in one RESPONSE or UPDATE frame. */
  public static final int PART_SIZE = 60 * 1024;

  /** Bytes of the login nonce. */
  public static final int NONCE_BYTES = 32;

  /** Data ids start here (they are assigned by the server in registration order). */
  public static final int FIRST_DATA_ID = 1;

  /** Data flag: the data can be subscribed to (it is published). */
  public static final int FLAG_SUBSCRIBABLE = 1;
}
