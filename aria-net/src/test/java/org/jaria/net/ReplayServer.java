package org.jaria.net;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.jaria.net.protocol.Protocol;

/**
 * Plays an ARIA server's recorded side of a session (see {@link PeerRecording}) to one client, in
 * step with it: the introduction, then, after the client's introduction, the login's packets (every
 * fixed command before the first data packet), then for each data request the client sends the
 * recorded answer to it — the next run of recorded packets of that request's command. What the
 * client sends is kept for the test to check.
 */
public final class ReplayServer implements AutoCloseable {

  private final ServerSocket socket;
  private final List<ArNetPacket> recorded;
  private final List<ArNetPacket> received = new java.util.concurrent.CopyOnWriteArrayList<>();
  private final Thread thread;
  private volatile Exception failure;

  /** Listens on a free loopback port and plays {@code s2c} (a recording's server bytes). */
  public ReplayServer(byte[] s2c) throws IOException {
    socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    recorded = PeerRecording.packets(s2c);
    thread = new Thread(this::serve, "replay-server");
    thread.start();
  }

  /** The port to connect to. */
  public int port() {
    return socket.getLocalPort();
  }

  /** What the client sent so far, in order. */
  public List<ArNetPacket> received() {
    return List.copyOf(received);
  }

  /** What went wrong on the server's side, or null. */
  public Exception failure() {
    return failure;
  }

  private void serve() {
    try (Socket s = socket.accept()) {
      OutputStream out = s.getOutputStream();
      DataInputStream in = new DataInputStream(s.getInputStream());
      int next = 0;
      out.write(recorded.get(next++).toWire());
      received.add(read(in));
      while (next < recorded.size() && recorded.get(next).getCommand() < 256) {
        out.write(recorded.get(next++).toWire());
      }
      out.flush();
      while (true) {
        ArNetPacket p = read(in);
        received.add(p);
        int cmd =
            p.getCommand() == Protocol.CLIENT_REQUEST ? p.toReader().bufToUByte2() : p.getCommand();
        if (cmd < 256) {
          continue;
        }
        // Skip to the recorded answer of this command and send its run of packets.
        while (next < recorded.size() && recorded.get(next).getCommand() != cmd) {
          next++;
        }
        List<ArNetPacket> run = new ArrayList<>();
        while (next < recorded.size() && recorded.get(next).getCommand() == cmd) {
          run.add(recorded.get(next++));
        }
        for (ArNetPacket r : run) {
          out.write(r.toWire());
        }
        out.flush();
      }
    } catch (java.io.EOFException e) {
      // the client left
    } catch (IOException e) {
      if (!socket.isClosed()) {
        failure = e;
      }
    }
  }

  private static ArNetPacket read(DataInputStream in) throws IOException {
    byte[] h = new byte[4];
    in.readFully(h);
    int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
    byte[] w = new byte[len];
    System.arraycopy(h, 0, w, 0, 4);
    in.readFully(w, 4, len - 4);
    return ArNetPacket.fromWire(w, 0, len);
  }

  @Override
  public void close() throws IOException {
    socket.close();
    try {
      thread.join(5000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
