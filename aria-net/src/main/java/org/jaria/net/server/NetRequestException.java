package org.jaria.net.server;

import org.jaria.net.protocol.NetError;

/** Thrown by a request handler to answer the request with a specific error code and message. */
public class NetRequestException extends Exception {

  private static final long serialVersionUID = 1L;

  private final NetError code;

  /** An error reply. */
  public NetRequestException(NetError code, String message) {
    super(message);
    this.code = code;
  }

  /** The code sent to the client. */
  public NetError getCode() {
    return code;
  }
}
