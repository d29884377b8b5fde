package org.jaria.net.client;

import org.jaria.net.protocol.NetError;

/**
 * A request or a connection failed: the server refused the login, answered a request with an error,
 * went away, or did not answer in time. {@link #getCode()} says which server error it was (null for
 * local failures such as a lost connection).
 */
public class ArClientException extends Exception {

  private static final long serialVersionUID = 1L;

  private final transient NetError code;

  /** A failure with the server's error code (or null) and a message saying what happened. */
  public ArClientException(NetError code, String message) {
    super(message);
    this.code = code;
  }

  /** A local failure caused by {@code cause}. */
  public ArClientException(String message) {
    super(message);
    this.code = null;
  }

  public ArClientException(String message, Throwable cause) {
    super(message, cause);
    this.code = null;
  }

  /** The server's error code, or null. */
  public NetError getCode() {
    return code;
  }
}
