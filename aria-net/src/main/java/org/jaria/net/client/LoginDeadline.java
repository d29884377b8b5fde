package org.jaria.net.client;

import java.io.FilterInputStream;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.time.Duration;

/**
 * The input of a socket that is logging in: every read may wait only for what is left of the login
 * time, so a server that sends its introduction one byte at a time cannot stretch the login beyond
 * the connect timeout. After {@link #lift()} reads wait as long as they need (ArNetworking servers
 * may be silent for a long time once logged in).
 */
final class LoginDeadline extends FilterInputStream {

  private final Socket socket;
  private final long deadlineNanos;
  private volatile boolean lifted;

  LoginDeadline(Socket socket, Duration timeout) throws IOException {
    super(socket.getInputStream());
    this.socket = socket;
    this.deadlineNanos = System.nanoTime() + timeout.toNanos();
    bound();
  }

  /** Ends the deadline: reads block until data comes. */
  void lift() throws IOException {
    lifted = true;
    socket.setSoTimeout(0);
  }

  private void bound() throws IOException {
    if (lifted) {
      return;
    }
    long left = deadlineNanos - System.nanoTime();
    if (left <= 0) {
      throw new SocketTimeoutException("the login took longer than the connect timeout");
    }
    socket.setSoTimeout((int) Math.max(1, Math.min(Integer.MAX_VALUE, left / 1_000_000)));
  }

  @Override
  public int read() throws IOException {
    bound();
    return super.read();
  }

  @Override
  public int read(byte[] b, int off, int len) throws IOException {
    bound();
    return super.read(b, off, len);
  }
}
