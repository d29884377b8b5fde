package org.jaria.connection;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.net.UnknownHostException;
import org.jaria.clock.Clock;

/**
 * A TCP connection to a robot server: a simulator (port 8101 by default), a serial-to-Ethernet
 * bridge, or an onboard {@code ipthru} relay (ARIA's {@code ArTcpConnection}). Nagle's algorithm is
 * off so that each command leaves at once.
 */
public final class ArTcpConnection implements ArDeviceConnection {

  /** The simulator's default port. */
  public static final int DEFAULT_PORT = 8101;

  private static final int CONNECT_TIMEOUT_MS = 3000;

  private final String host;
  private final int port;
  private final Clock clock;
  private volatile Socket socket;
  private InputStream in;
  private OutputStream out;
  private volatile Status status = Status.NEVER_OPENED;
  private volatile String openMessage = "";
  private volatile long timeRead;
  private int currentTimeout = -1;

  /** A connection to {@code host:port} timed by the system clock (not yet open). */
  public ArTcpConnection(String host, int port) {
    this(host, port, Clock.system());
  }

  /** A connection to {@code host:port} (not yet open). */
  public ArTcpConnection(String host, int port, Clock clock) {
    this.host = host;
    this.port = port;
    this.clock = clock;
  }

  /** Wraps a socket that is already connected (a server's accepted client). */
  public static ArTcpConnection wrap(Socket connected, Clock clock) throws IOException {
    ArTcpConnection c =
        new ArTcpConnection(
            connected.getInetAddress().getHostAddress(), connected.getPort(), clock);
    c.adopt(connected);
    return c;
  }

  @Override
  public synchronized void open() throws IOException {
    if (status == Status.OPEN) {
      return;
    }
    Socket s = new Socket();
    try {
      s.connect(new InetSocketAddress(host, port), CONNECT_TIMEOUT_MS);
      adopt(s);
    } catch (UnknownHostException e) {
      fail(s, "unknown host '" + host + "': check the name given with -remoteHost");
    } catch (ConnectException | SocketTimeoutException e) {
      fail(
          s,
          "nothing accepts connections at "
              + host
              + ":"
              + port
              + " ("
              + e.getMessage()
              + "): start the simulator (./jaria sim) or check -remoteHost/-remoteRobotTcpPort");
    } catch (IOException e) {
      fail(
          s,
          "could not connect to "
              + host
              + ":"
              + port
              + ": "
              + e.getMessage()
              + " (is the robot or simulator running there?)");
    }
  }

  private void adopt(Socket s) throws IOException {
    s.setTcpNoDelay(true);
    in = s.getInputStream();
    out = s.getOutputStream();
    socket = s;
    openMessage = "";
    status = Status.OPEN;
  }

  private void fail(Socket s, String message) throws IOException {
    try {
      s.close();
    } catch (IOException ignored) {
      // nothing more to release
    }
    openMessage = message;
    status = Status.OPEN_FAILED;
    throw new IOException(message);
  }

  @Override
  public Status getStatus() {
    return status;
  }

  @Override
  public String getOpenMessage() {
    return openMessage;
  }

  @Override
  public int read(byte[] buf, int off, int len, long timeoutMs) throws IOException {
    Socket s = requireOpen();
    try {
      if (timeoutMs <= 0) {
        int avail = in.available();
        if (avail <= 0) {
          return 0;
        }
        len = Math.min(len, avail);
      } else if (currentTimeout != timeoutMs) {
        s.setSoTimeout((int) Math.min(Integer.MAX_VALUE, timeoutMs));
        currentTimeout = (int) timeoutMs;
      }
      int n = in.read(buf, off, len);
      if (n < 0) {
        status = Status.CLOSED_ERROR;
        return -1;
      }
      if (n > 0) {
        timeRead = clock.nanoTime();
      }
      return n;
    } catch (SocketTimeoutException e) {
      return 0;
    } catch (IOException e) {
      if (status == Status.OPEN) {
        status = Status.CLOSED_ERROR;
      }
      throw e;
    }
  }

  @Override
  public void write(byte[] buf, int off, int len) throws IOException {
    requireOpen();
    try {
      out.write(buf, off, len);
      out.flush();
    } catch (IOException e) {
      if (status == Status.OPEN) {
        status = Status.CLOSED_ERROR;
      }
      throw e;
    }
  }

  private Socket requireOpen() throws IOException {
    Socket s = socket;
    if (s == null || status != Status.OPEN) {
      if (status == Status.CLOSED_ERROR) {
        throw new EOFException(getPortName() + " was closed by the other end");
      }
      throw new IOException(getPortName() + " is not open (status " + status + ")");
    }
    return s;
  }

  @Override
  public void close() {
    // Mark first: a reader woken by the closing socket must not report an error.
    if (status == Status.OPEN) {
      status = Status.CLOSED_NORMALLY;
    }
    Socket s = socket;
    if (s != null) {
      try {
        s.close();
      } catch (IOException ignored) {
        // closing anyway
      }
    }
  }

  @Override
  public long getTimeRead() {
    return timeRead;
  }

  @Override
  public Clock clock() {
    return clock;
  }

  @Override
  public String getPortName() {
    return "tcp " + host + ":" + port;
  }

  @Override
  public String toString() {
    return getPortName() + " (" + status + ")";
  }
}
