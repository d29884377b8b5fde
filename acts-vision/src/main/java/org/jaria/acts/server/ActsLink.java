package org.jaria.acts.server;

import java.io.IOException;
import org.jaria.acts.ActsProtocol;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.connection.ArDeviceConnection;

/**
 * ACTS over one connection that the caller drives, without threads: each {@link #pump()} reads the
 * client's requests and answers every {@code '0'} with the blobs of a freshly processed frame. A
 * simulator in lockstep pumps it every tick, with the client's end of an in-memory pipe given to
 * {@code ArACTS_1_2.openPort(robot, connection)}; the TCP {@link ActsServer} is the same protocol
 * with threads and sockets.
 */
public final class ActsLink {

  private final VisionPipeline pipeline;
  private final ArDeviceConnection conn;
  private final BlobFrame frame = new BlobFrame();
  private final byte[] in = new byte[256];
  private final byte[] reply = new byte[ActsProtocol.MAX_REPLY];
  private boolean quitRequested;
  private long requestsServed;

  /** ACTS answering on {@code conn} (the server's end) with frames from {@code pipeline}. */
  public ActsLink(VisionPipeline pipeline, ArDeviceConnection conn) {
    this.pipeline = pipeline;
    this.conn = conn;
  }

  /**
   * Answers whatever the client has sent since the last call. Garbage bytes are ignored, as the
   * real server does.
   *
   * @throws IOException if the connection failed or the image source did
   */
  public void pump() throws IOException {
    if (conn.getStatus() != ArDeviceConnection.Status.OPEN) {
      return;
    }
    int n;
    while ((n = conn.read(in, 0, in.length, 0)) > 0) {
      for (int i = 0; i < n; i++) {
        if (in[i] == ActsProtocol.REQUEST_PACKET) {
          answer();
        } else if (in[i] == ActsProtocol.REQUEST_QUIT) {
          quitRequested = true;
        }
      }
    }
  }

  private void answer() throws IOException {
    if (!pipeline.processNext(frame)) {
      return;
    }
    int len = ActsReply.encode(frame, reply);
    conn.write(reply, 0, len);
    requestsServed++;
  }

  /** Whether the client sent the quit byte. */
  public boolean isQuitRequested() {
    return quitRequested;
  }

  /** Requests answered. */
  public long requestsServed() {
    return requestsServed;
  }

  /** The last frame's blobs. */
  public BlobFrame lastFrame() {
    return frame;
  }
}
