package org.jaria.net.protocol;

/**
 * Error, refusal and closing codes (see {@code PROTOCOL.md}). Codes 1–19 answer one request (the
 * connection stays up), 20–29 refuse a login, 30–39 say why the server closes a connection.
 */
public enum NetError {
  /** No data with that id or name. */
  UNKNOWN_DATA(1),
  /** The arguments did not decode or were out of range. */
  BAD_ARGUMENTS(2),
  /** The user's groups do not include the data's command group. */
  NOT_ALLOWED(3),
  /** Too many requests in flight; try again later. */
  BUSY(4),
  /** The handler failed; the message says why. */
  FAILED(5),
  /** This data cannot be subscribed to (it is a command). */
  NOT_SUBSCRIBABLE(6),
  /** The client already has the most subscriptions allowed. */
  TOO_MANY_SUBSCRIPTIONS(7),
  /** The service behind the data is not available on this robot. */
  UNAVAILABLE(8),
  /** The client speaks a protocol version the server does not. */
  BAD_VERSION(20),
  /** Wrong user name or password. */
  BAD_LOGIN(21),
  /** The server has its maximum number of clients. */
  SERVER_FULL(22),
  /** The client did not log in in time. */
  LOGIN_TIMEOUT(23),
  /** The server is shutting down. */
  SHUTTING_DOWN(24),
  /** A frame that is not a well-formed message. */
  MALFORMED(30),
  /** The client does not read fast enough; its queue overflowed or stalled. */
  TOO_SLOW(31),
  /** Nothing heard from the client for too long. */
  IDLE(32),
  /** A message that is not allowed at this point of the conversation. */
  PROTOCOL(33),
  /** The client said goodbye. */
  BYE(34);

  private final int code;

  NetError(int code) {
    this.code = code;
  }

  /** The number on the wire. */
  public int code() {
    return code;
  }

  /** The error with this number, or null. */
  public static NetError fromCode(long code) {
    for (NetError e : values()) {
      if (e.code == code) {
        return e;
      }
    }
    return null;
  }
}
