package org.jaria.net;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import org.jaria.net.protocol.LoginDigest;
import org.jaria.net.protocol.Protocol;

/**
 * A bare ArNetworking socket for tests: sends exactly the bytes a test wants (including garbage)
 * and reads packets one by one, as ARIA's C++ client would see them.
 */
public final class RawClient implements AutoCloseable {

  private final Socket socket;
  private final DataInputStream in;
  private final OutputStream out;
  private String passwordKey = "";

  /** Connects to the server on the loopback address. */
  public RawClient(int port) throws IOException {
    this(port, 0);
  }

  /** Connects with a small receive buffer (a client that reads slowly), 0 for the default. */
  public RawClient(int port, int receiveBuffer) throws IOException {
    this(port, receiveBuffer, null);
  }

  /**
   * Connects from local address {@code from} (another address of 127.0.0.0/8, say: a client on
   * another computer as far as the server can tell), null for any.
   */
  public RawClient(int port, int receiveBuffer, String from) throws IOException {
    socket = new Socket();
    if (receiveBuffer > 0) {
      socket.setReceiveBufferSize(receiveBuffer);
    }
    if (from != null) {
      socket.bind(new InetSocketAddress(InetAddress.getByName(from), 0));
    }
    socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 5000);
    socket.setSoTimeout(20_000);
    in = new DataInputStream(socket.getInputStream());
    out = socket.getOutputStream();
  }

  /** Sends raw bytes. */
  public void send(byte[] bytes) throws IOException {
    out.write(bytes);
    out.flush();
  }

  /** Sends a packet. */
  public void send(ArNetPacket p) throws IOException {
    send(p.toWire());
  }

  /** Sends a request once: command {@code command} with {@code body}. */
  public void requestOnce(int command, ArNetPacket body) throws IOException {
    ArNetPacket p = new ArNetPacket(command);
    p.dataToBuf(body.toByteArray());
    send(p);
  }

  /** Sends ArNetworking's REQUEST for {@code command} every {@code ms}. */
  public void request(int command, int ms) throws IOException {
    ArNetPacket p = new ArNetPacket(Protocol.CLIENT_REQUEST);
    p.uByte2ToBuf(command).byte4ToBuf(ms);
    send(p);
  }

  /** Bytes that can be read now without waiting. */
  public int available() throws IOException {
    return in.available();
  }

  /** Reads one packet. */
  public ArNetPacket read() throws IOException {
    byte[] h = new byte[4];
    in.readFully(h);
    int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
    if (len < 8 || len > ArNetPacket.MAX_LENGTH) {
      throw new IOException("a packet of " + len + " bytes");
    }
    byte[] w = new byte[len];
    System.arraycopy(h, 0, w, 0, 4);
    in.readFully(w, 4, len - 4);
    return ArNetPacket.fromWire(w, 0, len);
  }

  /** Reads until a packet of {@code command}. */
  public ArNetPacket readUntil(int command) throws IOException {
    while (true) {
      ArNetPacket p = read();
      if (p.getCommand() == command) {
        return p;
      }
    }
  }

  /**
   * Reads until one packet of each of {@code commands} has come, whatever their order (a worker's
   * answer may overtake or trail an answer sent at once), and returns the first of each by command.
   */
  public java.util.Map<Integer, ArNetPacket> readUntilAll(int... commands) throws IOException {
    java.util.Map<Integer, ArNetPacket> got = new java.util.HashMap<>();
    java.util.Set<Integer> wanted = new java.util.HashSet<>();
    for (int c : commands) {
      wanted.add(c);
    }
    while (!got.keySet().containsAll(wanted)) {
      ArNetPacket p = read();
      if (wanted.contains(p.getCommand())) {
        got.putIfAbsent(p.getCommand(), p);
      }
    }
    return got;
  }

  /** Reads the server's introduction (keeping its password key). */
  public ArNetPacket readIntroduction() throws IOException {
    ArNetPacket p = readUntil(Protocol.SERVER_INTRODUCTION);
    p.bufToStr();
    p.bufToUByte2();
    p.bufToUByte4();
    p.bufToUByte4();
    passwordKey = p.bufToStr();
    p.resetRead();
    return p;
  }

  /**
   * Logs in as ARIA's client does (introduction with the MD5 digest, TCP only) and returns the
   * server's answer: CONNECTED or REJECTED.
   */
  public ArNetPacket login(String user, String password) throws IOException {
    readIntroduction();
    ArNetPacket p = new ArNetPacket(Protocol.CLIENT_INTRODUCTION);
    p.uByte2ToBuf(0)
        .strToBuf(user)
        .dataToBuf(LoginDigest.digest("", passwordKey, password == null ? "" : password))
        .strToBuf("")
        .byteToBuf(0);
    send(p);
    send(new ArNetPacket(Protocol.CLIENT_TCP_ONLY));
    while (true) {
      ArNetPacket a = read();
      if (a.getCommand() == Protocol.SERVER_CONNECTED
          || a.getCommand() == Protocol.SERVER_REJECTED) {
        return a;
      }
    }
  }

  /**
   * Reads until the server closes the connection: returns the REJECTED reason or SHUTDOWN's command
   * (1) if one came last, else -1.
   */
  public long readUntilClosed() throws IOException {
    long last = -1;
    try {
      while (true) {
        ArNetPacket p = read();
        if (p.getCommand() == Protocol.SERVER_SHUTDOWN) {
          last = Protocol.SERVER_SHUTDOWN;
        } else if (p.getCommand() == Protocol.SERVER_REJECTED) {
          last = p.bufToByte2();
        }
      }
    } catch (EOFException | SocketException e) {
      return last;
    } catch (ArNetPacketException e) {
      return -1;
    }
  }

  @Override
  public void close() throws IOException {
    socket.close();
  }
}
