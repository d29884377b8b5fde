package org.jaria.sim.server;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.packets.PacketIds;

/**
 * A test client that talks to the simulator over a real socket exactly as ARIA's ArRobot does in
 * its handshake: SYNC0, SYNC1, SYNC2 (no argument) with echoes, name/type/subtype from the SYNC2
 * reply, OPEN with int 1, CLOSE with int 1. Reads whole frames and checks nothing itself; the tests
 * look at the bytes.
 */
public final class AriaLikeTcpClient implements AutoCloseable {

  final Socket socket;
  private final InputStream in;
  private final OutputStream out;
  private final ArRobotPacket pkt = new ArRobotPacket();

  /** Name, type and subtype from the SYNC2 reply (after {@link #connectLikeAria}). */
  public String name;

  /** The robot type. */
  public String type;

  /** The robot subtype, lower-cased. */
  public String subtype;

  /** Connects to the simulator on localhost:{@code port}. */
  public AriaLikeTcpClient(int port) throws IOException {
    socket = new Socket();
    socket.connect(new InetSocketAddress(java.net.InetAddress.getLoopbackAddress(), port), 5000);
    socket.setTcpNoDelay(true);
    socket.setSoTimeout(5000);
    in = socket.getInputStream();
    out = socket.getOutputStream();
  }

  void write(ArRobotPacket p) throws IOException {
    out.write(p.getBuf(), 0, p.getLength());
    out.flush();
  }

  void writeRaw(byte[] b) throws IOException {
    out.write(b);
    out.flush();
  }

  void com(int cmd) throws IOException {
    write(CommandCodec.com(pkt, cmd));
  }

  /** Sends a command without argument. */
  public void com(ArCommands cmd) throws IOException {
    com(cmd.getNumber());
  }

  /** Sends a command with an integer argument. */
  public void comInt(ArCommands cmd, int v) throws IOException {
    comInt(cmd.getNumber(), v);
  }

  public void comInt(int cmd, int v) throws IOException {
    write(CommandCodec.comInt(pkt, cmd, v));
  }

  /** Reads one whole frame (header to checksum) as raw bytes; fails on a read timeout. */
  byte[] readFrame() throws IOException {
    DataInputStream d = new DataInputStream(in);
    int b;
    while ((b = d.readUnsignedByte()) != 0xFA) {
      // resynchronise, as a client must
    }
    int b2 = d.readUnsignedByte();
    if (b2 != 0xFB) {
      return readFrame();
    }
    int count = d.readUnsignedByte();
    byte[] frame = new byte[count + 3];
    frame[0] = (byte) 0xFA;
    frame[1] = (byte) 0xFB;
    frame[2] = (byte) count;
    d.readFully(frame, 3, count);
    return frame;
  }

  /** Reads frames until one has this ID. */
  public ArRobotPacket readUntil(int id) throws IOException {
    for (int i = 0; i < 500; i++) {
      byte[] f = readFrame();
      if ((f[3] & 0xFF) == id) {
        return new ArRobotPacket().load(f, 0, f.length);
      }
    }
    throw new IOException("no packet with ID " + id + " among 500");
  }

  /**
   * ARIA's connect: send SYNC{state}, read one packet; a standard SIP means a robot still open from
   * an earlier client, so send CLOSE 1, drain what is in flight and start over; a reply with
   * another ID restarts the sequence; after SYNC2 read the identification, then OPEN 1.
   */
  public void connectLikeAria() throws IOException {
    int state = 0;
    for (int tries = 0; state < 3; tries++) {
      if (tries > 50) {
        throw new IOException("no handshake after 50 tries");
      }
      com(state);
      byte[] reply = readFrame();
      int id = reply[3] & 0xFF;
      if (id == PacketIds.SIP_STOPPED) {
        comInt(ArCommands.CLOSE, 1);
        drain();
        state = 0;
      } else if (id != state) {
        state = 0;
      } else {
        if (state == 2) {
          ArRobotPacket p = new ArRobotPacket().load(reply, 0, reply.length);
          name = p.bufToString();
          type = p.bufToString();
          subtype = p.bufToString().toLowerCase(java.util.Locale.ROOT);
        }
        state++;
      }
    }
    comInt(ArCommands.OPEN, 1);
  }

  /** Reads and discards until nothing arrives for 300 ms (ARIA waits out the rest of a cycle). */
  private void drain() throws IOException {
    int old = socket.getSoTimeout();
    socket.setSoTimeout(300);
    try {
      while (true) {
        readFrame();
      }
    } catch (java.net.SocketTimeoutException quiet) {
      // nothing more in flight
    } finally {
      socket.setSoTimeout(old);
    }
  }

  @Override
  public void close() throws IOException {
    socket.close();
  }
}
