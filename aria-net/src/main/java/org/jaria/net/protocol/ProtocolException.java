package org.jaria.net.protocol;

/**
 * A peer broke the protocol: bytes that are not an ArNetworking packet (bad sync bytes, length or
 * checksum), or a packet that is not allowed at this point (anything but the introduction before
 * logging in). The connection to that peer is closed.
 */
public class ProtocolException extends Exception {

  private static final long serialVersionUID = 1L;

  private final NetError code;

  /** An exception with the closing code to send and a message saying what was wrong. */
  public ProtocolException(NetError code, String message) {
    super(message);
    this.code = code;
  }

  /** As above, with the decoder's exception. */
  public ProtocolException(NetError code, String message, Throwable cause) {
    super(message, cause);
    this.code = code;
  }

  /** The code sent to the peer before closing. */
  public NetError getCode() {
    return code;
  }
}
