package org.jaria.net;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.net.protocol.Protocol;

/**
 * Plays an ARIA server's recorded side of a connection back to a client under test, answering
 * request by request: its introduction at once, the rest of its login (lists, connected) when the
 * client introduces itself, and then, for every data request the client sends, the next recorded
 * packet of that data. So a client that asks in its own rhythm still gets the recorded answers in
 * the recorded order, with no race against the recording's timing.
 */
public final class RecordedServer implements AutoCloseable {

  private final ServerSocket socket;
  private final Thread thread;
  private final List<ArNetPacket> login;
  private final Map<Integer, Deque<List<ArNetPacket>>> answers = new HashMap<>();
  private final AtomicInteger requests = new AtomicInteger();
  private volatile ArNetPacket clientIntroduction;

  /** Serves the recorded server side {@code s2c} (a resource under {@code peers/}). */
  public RecordedServer(String s2c) throws IOException {
    List<ArNetPacket> all = PeerRecording.packets(PeerRecording.bytes(s2c));
    int firstData = 0;
    while (firstData < all.size()
        && all.get(firstData).getCommand() < Protocol.FIRST_DATA_COMMAND) {
      firstData++;
    }
    login = all.subList(0, firstData);
    // An answer is one packet, or (ArNetworking's RETURN_UNTIL_EMPTY, as getConfigBySections) a
    // run of packets of one data ended by an empty one.
    List<ArNetPacket> data = all.subList(firstData, all.size());
    for (int i = 0; i < data.size(); ) {
      int cmd = data.get(i).getCommand();
      int end = i;
      while (end < data.size()
          && data.get(end).getCommand() == cmd
          && data.get(end).getDataLength() > 0) {
        end++;
      }
      boolean endsEmpty = end < data.size() && data.get(end).getCommand() == cmd && end > i;
      int next = endsEmpty ? end + 1 : i + 1;
      answers.computeIfAbsent(cmd, k -> new ArrayDeque<>()).add(List.copyOf(data.subList(i, next)));
      i = next;
    }
    socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    thread = new Thread(this::serve, "test-recorded-server");
    thread.setDaemon(true);
    thread.start();
  }

  /** The port to connect to. */
  public int getPort() {
    return socket.getLocalPort();
  }

  /** Data requests the client has sent (requests once and at an interval). */
  public int requestsSeen() {
    return requests.get();
  }

  /** The client's introduction packet, once it has sent it. */
  public ArNetPacket clientIntroduction() {
    return clientIntroduction;
  }

  private void serve() {
    try (Socket s = socket.accept()) {
      OutputStream out = s.getOutputStream();
      DataInputStream in = new DataInputStream(s.getInputStream());
      out.write(login.get(0).toWire());
      while (true) {
        byte[] h = new byte[4];
        in.readFully(h);
        int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
        byte[] w = new byte[len];
        System.arraycopy(h, 0, w, 0, 4);
        in.readFully(w, 4, len - 4);
        ArNetPacket p = ArNetPacket.fromWire(w, 0, len);
        int cmd = p.getCommand();
        if (cmd == Protocol.CLIENT_INTRODUCTION) {
          clientIntroduction = p;
          for (ArNetPacket l : login.subList(1, login.size())) {
            out.write(l.toWire());
          }
        } else if (cmd == Protocol.CLIENT_REQUEST || cmd >= Protocol.FIRST_DATA_COMMAND) {
          requests.incrementAndGet();
          int data = cmd == Protocol.CLIENT_REQUEST ? p.toReader().bufToUByte2() : cmd;
          Deque<List<ArNetPacket>> q = answers.get(data);
          List<ArNetPacket> a = q == null ? null : q.poll();
          if (a != null) {
            for (ArNetPacket part : a) {
              out.write(part.toWire());
            }
          }
        }
        out.flush();
      }
    } catch (IOException | RuntimeException e) {
      // the client left, or the test closed the server
    }
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
