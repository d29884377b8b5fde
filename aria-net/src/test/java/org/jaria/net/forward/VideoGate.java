package org.jaria.net.forward;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.net.ArNetPacket;

/**
 * What stands between a forwarder and its video server in the hostile tests: a port that relays to
 * a real video server packet by packet, and that the test can make misbehave — cut every
 * connection, keep the server's frames back, slip packets or garbage into the stream, or answer new
 * connections with garbage or silence.
 */
final class VideoGate implements AutoCloseable {

  /** What a new connection meets. */
  enum Mode {
    RELAY,
    GARBAGE,
    SILENT
  }

  private final ServerSocket socket;
  private final int upstreamPort;
  private final Thread acceptor;
  private final List<Link> links = new CopyOnWriteArrayList<>();
  private volatile Mode mode = Mode.RELAY;
  private volatile int heldBackCommand = -1;

  VideoGate(int upstreamPort) throws IOException {
    this.upstreamPort = upstreamPort;
    socket = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
    acceptor = new Thread(this::accept, "test-video-gate");
    acceptor.setDaemon(true);
    acceptor.start();
  }

  int getPort() {
    return socket.getLocalPort();
  }

  void setMode(Mode m) {
    mode = m;
  }

  /** Packets of this command from the server are dropped (-1: none). */
  void holdBack(int command) {
    heldBackCommand = command;
  }

  /** Closes every open connection (the video server "disappears"); new ones are accepted. */
  void cutAll() {
    for (Link l : links) {
      l.close();
    }
    links.clear();
  }

  /** Writes {@code bytes} into every relayed stream towards the forwarder, between packets. */
  void inject(byte[] bytes) throws IOException {
    for (Link l : links) {
      l.toClient(bytes);
    }
  }

  int openLinks() {
    return links.size();
  }

  private void accept() {
    while (!socket.isClosed()) {
      try {
        Socket c = socket.accept();
        switch (mode) {
          case RELAY -> {
            Socket up = new Socket(InetAddress.getLoopbackAddress(), upstreamPort);
            Link l = new Link(c, up);
            links.add(l);
            l.start();
          }
          case GARBAGE -> {
            c.getOutputStream()
                .write(
                    "HTTP/1.0 200 OK\r\n\r\nnot a video server"
                        .getBytes(StandardCharsets.US_ASCII));
            c.close();
          }
          case SILENT -> links.add(new Link(c, null)); // held open, never answered
        }
      } catch (IOException e) {
        // closed, or one connection failed: go on until the gate closes
      }
    }
  }

  @Override
  public void close() throws IOException {
    socket.close();
    cutAll();
    try {
      acceptor.join(5000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** One relayed connection. */
  private final class Link {
    private final Socket client;
    private final Socket server;
    private final Object writeLock = new Object();

    Link(Socket client, Socket server) {
      this.client = client;
      this.server = server;
    }

    void start() {
      Thread up = new Thread(this::clientToServer, "test-video-gate-up");
      Thread down = new Thread(this::serverToClient, "test-video-gate-down");
      up.setDaemon(true);
      down.setDaemon(true);
      up.start();
      down.start();
    }

    private void clientToServer() {
      try (InputStream in = client.getInputStream()) {
        OutputStream out = server.getOutputStream();
        in.transferTo(out);
      } catch (IOException e) {
        // cut
      } finally {
        close();
      }
    }

    private void serverToClient() {
      try (DataInputStream in = new DataInputStream(server.getInputStream())) {
        while (true) {
          byte[] h = new byte[4];
          in.readFully(h);
          int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
          byte[] w = new byte[len];
          System.arraycopy(h, 0, w, 0, 4);
          in.readFully(w, 4, len - 4);
          if (ArNetPacket.fromWire(w, 0, len).getCommand() != heldBackCommand) {
            toClient(w);
          }
        }
      } catch (IOException | RuntimeException e) {
        // cut
      } finally {
        close();
      }
    }

    void toClient(byte[] bytes) throws IOException {
      synchronized (writeLock) {
        client.getOutputStream().write(bytes);
      }
    }

    void close() {
      try {
        client.close();
        if (server != null) {
          server.close();
        }
      } catch (IOException e) {
        // closing anyway
      }
    }
  }
}
