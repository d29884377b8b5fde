package org.jaria.net;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import org.jaria.net.protocol.Frames;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.PasswordHash;
import org.jaria.net.protocol.Protocol;

/**
 * A client that speaks the protocol by hand, frame by frame, for tests that send what a good client
 * never would (garbage, wrong order, nothing at all) or read what the server sends exactly. Every
 * read times out after 10 s, so a test never hangs on a server that stays silent.
 */
public final class RawClient implements AutoCloseable {

  /** A frame received: its kind and the packet positioned after the kind. */
  public record Frame(Kind kind, ArNetPacket body) {}

  private final Socket socket;
  private final DataInputStream in;
  private final OutputStream out;

  /** Connects to {@code port} on this machine. */
  public RawClient(int port) throws IOException {
    this(port, 0);
  }

  /**
   * Connects to {@code port} with a receive buffer of {@code receiveBuffer} bytes (0: the
   * system's), before connecting so the window is small from the start.
   */
  public RawClient(int port, int receiveBuffer) throws IOException {
    socket = new Socket();
    if (receiveBuffer > 0) {
      socket.setReceiveBufferSize(receiveBuffer);
    }
    socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 10_000);
    socket.setSoTimeout(10_000);
    socket.setTcpNoDelay(true);
    in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
    out = socket.getOutputStream();
  }

  /** Sends raw bytes. */
  public void send(byte[] bytes) throws IOException {
    out.write(bytes);
    out.flush();
  }

  /** Sends a frame of {@code kind} with {@code values}. */
  public void send(Kind kind, Object... values) throws IOException {
    send(Frames.frame(kind, values));
  }

  /** Reads one frame (fails the read after 10 s of silence). */
  public Frame read() throws IOException {
    int len = in.readInt();
    if (len <= 0 || len > (64 << 20)) {
      throw new IOException("bad frame length " + len);
    }
    byte[] b = new byte[len];
    in.readFully(b);
    ArNetPacket p = ArNetPacket.wrap(b);
    return new Frame(Kind.fromCode(p.bufToLong()), p);
  }

  /** Reads frames until one of {@code kind}, skipping updates and others. */
  public Frame readUntil(Kind kind) throws IOException {
    while (true) {
      Frame f = read();
      if (f.kind() == kind) {
        return f;
      }
    }
  }

  /**
   * Logs in: HELLO, CHALLENGE, LOGIN, then returns the server's answer (WELCOME or REFUSED).
   *
   * @param password null for a server that needs none
   */
  public Frame login(String user, String password) throws IOException {
    send(Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, "raw", user);
    Frame ch = read();
    if (ch.kind() != Kind.CHALLENGE) {
      return ch;
    }
    ArNetPacket p = ch.body();
    p.bufToStr();
    p.bufToLong();
    p.bufToStr();
    byte[] nonce = p.bufToData();
    byte[] salt = p.bufToData();
    int iterations = p.bufToInt();
    byte[] proof = new byte[0];
    if (iterations > 0) {
      proof =
          PasswordHash.proof(
              PasswordHash.derive(password == null ? "" : password, salt, iterations), nonce);
    }
    send(Kind.LOGIN, (Object) proof);
    return read();
  }

  /**
   * Reads until the server closes the connection.
   *
   * @return the code of the last CLOSING or REFUSED frame, or -1 if none came
   */
  public long readUntilClosed() throws IOException {
    long code = -1;
    try {
      while (true) {
        Frame f = read();
        if (f.kind() == Kind.CLOSING || f.kind() == Kind.REFUSED) {
          code = f.body().bufToLong();
        }
      }
    } catch (EOFException | SocketException e) {
      return code;
    } catch (SocketTimeoutException e) {
      throw new IOException("the server did not close the connection within 10 s", e);
    }
  }

  @Override
  public void close() throws IOException {
    socket.close();
  }
}
