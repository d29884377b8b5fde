package org.jaria.web.server;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * A test client of the server's WebSocket (the JDK's own client): everything it receives, queued.
 */
final class WsClient implements WebSocket.Listener, AutoCloseable {

  /** A received message: text, or binary (opcode, subscription, time, payload). */
  record Received(String text, ByteBuffer binary) {
    boolean isText() {
      return text != null;
    }
  }

  final BlockingQueue<Received> received = new LinkedBlockingQueue<>();
  final CompletableFuture<Integer> closed = new CompletableFuture<>();
  final WebSocket ws;
  private final boolean reading;
  private StringBuilder text = new StringBuilder();
  private ByteBuffer bin = ByteBuffer.allocate(0);

  private WsClient(URI uri, boolean reading, String... subprotocols) throws Exception {
    this.reading = reading;
    WebSocket.Builder b = HttpClient.newHttpClient().newWebSocketBuilder();
    if (subprotocols.length > 0) {
      b.subprotocols(
          subprotocols[0], java.util.Arrays.copyOfRange(subprotocols, 1, subprotocols.length));
    }
    ws = b.connectTimeout(Duration.ofSeconds(10)).buildAsync(uri, this).get(20, TimeUnit.SECONDS);
  }

  /** A Foxglove client that reads everything. */
  static WsClient connect(URI uri) throws Exception {
    return new WsClient(uri, true, "foxglove.websocket.v1");
  }

  /** A client that never reads after the first message (a slow reader). */
  static WsClient stalled(URI uri) throws Exception {
    return new WsClient(uri, false, "foxglove.websocket.v1");
  }

  static WsClient withProtocols(URI uri, String... protocols) throws Exception {
    return new WsClient(uri, true, protocols);
  }

  @Override
  public void onOpen(WebSocket webSocket) {
    webSocket.request(1);
  }

  @Override
  public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
    text.append(data);
    if (last) {
      received.add(new Received(text.toString(), null));
      text = new StringBuilder();
    }
    if (reading) {
      webSocket.request(1);
    }
    return null;
  }

  @Override
  public CompletionStage<?> onBinary(WebSocket webSocket, ByteBuffer data, boolean last) {
    ByteBuffer joined = ByteBuffer.allocate(bin.remaining() + data.remaining());
    joined.put(bin).put(data).flip();
    bin = joined;
    if (last) {
      received.add(new Received(null, bin.order(java.nio.ByteOrder.LITTLE_ENDIAN)));
      bin = ByteBuffer.allocate(0);
    }
    if (reading) {
      webSocket.request(1);
    }
    return null;
  }

  @Override
  public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
    closed.complete(statusCode);
    return null;
  }

  @Override
  public void onError(WebSocket webSocket, Throwable error) {
    closed.complete(-1);
  }

  void send(String s) throws Exception {
    ws.sendText(s, true).get(10, TimeUnit.SECONDS);
  }

  void send(ByteBuffer b) throws Exception {
    // The JDK's client masks eight bytes at a time in the buffer's own byte order, which scrambles
    // a
    // little-endian buffer's payload: hand it big-endian (the bytes are the same).
    ws.sendBinary(b.order(java.nio.ByteOrder.BIG_ENDIAN), true).get(10, TimeUnit.SECONDS);
  }

  /** The next received message that matches, within 20 s (others are skipped). */
  Received next(Predicate<Received> p) throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
    while (System.nanoTime() < deadline) {
      Received r = received.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
      if (r != null && p.test(r)) {
        return r;
      }
    }
    throw new AssertionError("nothing matching arrived within 20 s");
  }

  Received nextText(String op) throws InterruptedException {
    return next(r -> r.isText() && r.text().contains("\"op\":\"" + op + "\""));
  }

  /** Drains what has arrived so far. */
  List<Received> drain() {
    List<Received> l = new ArrayList<>();
    received.drainTo(l);
    return l;
  }

  @Override
  public void close() {
    ws.abort();
  }
}
