package org.jaria.net;

/**
 * A packet did not hold what its reader expected: a value of another type, fewer values than asked
 * for, a length that runs past the end, a number out of range. Server handlers that let it escape
 * answer the client with a "bad arguments" error carrying this message; the client library throws
 * it when a server's reply does not decode.
 */
public class ArNetPacketException extends RuntimeException {

  private static final long serialVersionUID = 1L;

  /** An exception with a message saying what was expected and what was found. */
  public ArNetPacketException(String message) {
    super(message);
  }

  /** An exception with a message and the decoder's own exception. */
  public ArNetPacketException(String message, Throwable cause) {
    super(message, cause);
  }
}
