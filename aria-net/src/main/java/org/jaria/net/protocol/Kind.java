package org.jaria.net.protocol;

/**
 * The kinds of frame, the first value of every frame (see {@code PROTOCOL.md}). Numbers below 10 go
 * from client to server, numbers from 10 from server to client.
 */
public enum Kind {
  /** Client: magic, protocol version, client name, user name. */
  HELLO(1),
  /** Client: the login proof (HMAC of the challenge nonce). */
  LOGIN(2),
  /** Client: request id, data id, arguments... — a request answered once. */
  CALL(3),
  /** Client: request id, data id, interval ms — send me this data at that rate. */
  SUBSCRIBE(4),
  /** Client: data id — stop sending me this data. */
  UNSUBSCRIBE(5),
  /** Client: token — answered by PONG with the same token. */
  PING(6),
  /** Client: leaving; the server closes the connection. */
  BYE(7),
  /** Server: magic, version, server name, nonce, salt, iterations. */
  CHALLENGE(11),
  /** Server: client id, min interval, max frame, the data list. */
  WELCOME(12),
  /** Server: code, reason; the connection is then closed. */
  REFUSED(13),
  /** Server: request id, data id, final?, payload part. */
  RESPONSE(14),
  /** Server: data id, version, final?, payload part. */
  UPDATE(15),
  /** Server: request id, data id, code, message. */
  ERROR(16),
  /** Server: the token of a PING. */
  PONG(17),
  /** Server: code, reason; the server is closing this connection. */
  CLOSING(18),
  /** Server: request id, data id, the interval granted, ms. */
  SUBSCRIBED(19);

  private static final Kind[] BY_CODE = new Kind[20];

  static {
    for (Kind k : values()) {
      BY_CODE[k.code] = k;
    }
  }

  private final int code;

  Kind(int code) {
    this.code = code;
  }

  /** The number on the wire. */
  public int code() {
    return code;
  }

  /** The kind with this number, or null. */
  public static Kind fromCode(long code) {
    return code >= 0 && code < BY_CODE.length ? BY_CODE[(int) code] : null;
  }
}
