package org.jaria.web.server;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicLong;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.eclipse.jetty.websocket.api.StatusCode;
import org.jaria.web.foxglove.ClientMessages;
import org.jaria.web.foxglove.ClientRequest;
import org.jaria.web.foxglove.ClientSession;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One WebSocket client. Reads its requests (each one admitted by the flood limit, then handled by
 * its {@link ClientSession}) and sends it messages without ever waiting: a message that would push
 * the bytes waiting for this client over the limit is dropped and counted, and a client that keeps
 * the limit full for longer than allowed is disconnected and counted. Jetty calls the listener
 * methods; the publisher calls {@link #send}. Public only because Jetty calls the listener methods
 * through method handles, which need a public class; nothing outside this package makes one.
 */
public final class ClientConnection implements Session.Listener.AutoDemanding {

  private static final Logger LOG = LoggerFactory.getLogger(ClientConnection.class);

  /** Flooded messages after which the client is disconnected. */
  static final int FLOOD_CLOSE = 1000;

  private final WebServer hub;
  private final ClientSession state;
  private final String remote;
  private final AtomicLong queued = new AtomicLong();
  private final AtomicLong floodedHere = new AtomicLong();
  private volatile Session session;

  /** Since when (System.nanoTime) the client's queue has been full, or -1. */
  private volatile long fullSince = -1;

  ClientConnection(WebServer hub, boolean mayPublish, String remote) {
    this.hub = hub;
    this.state = new ClientSession(mayPublish);
    this.remote = remote;
  }

  ClientSession state() {
    return state;
  }

  @Override
  public void onWebSocketOpen(Session s) {
    session = s;
    hub.opened(this);
  }

  @Override
  public void onWebSocketText(String text) {
    handle(ClientMessages.parse(text), text.length());
  }

  @Override
  public void onWebSocketBinary(ByteBuffer payload, Callback callback) {
    try {
      handle(ClientMessages.parse(payload), payload.remaining());
    } finally {
      callback.succeed();
    }
  }

  private void handle(ClientRequest request, int size) {
    if (!state.admit(hub.floodNanos())) {
      hub.counters().flooded.increment();
      if (floodedHere.incrementAndGet() == FLOOD_CLOSE) {
        LOG.warn(
            "web client {} floods ({} messages dropped): disconnecting it", remote, FLOOD_CLOSE);
        close(StatusCode.POLICY_VIOLATION, "too many messages");
      }
      return;
    }
    hub.handle(this, request, size);
  }

  @Override
  public void onWebSocketClose(int statusCode, String reason, Callback callback) {
    try {
      if (statusCode == StatusCode.MESSAGE_TOO_LARGE) {
        hub.counters().oversized.increment();
      }
      hub.closed(this);
    } finally {
      callback.succeed();
    }
  }

  @Override
  public void onWebSocketError(Throwable cause) {
    LOG.debug("web client {}: {}", remote, cause.toString());
  }

  /** Sends text (a protocol message), within the queue limit. */
  void sendText(String text) {
    Session s = session;
    int size = text.getBytes(StandardCharsets.UTF_8).length;
    if (s != null && admitSend(size)) {
      s.sendText(text, sent(size));
    }
  }

  /** Sends a binary message, within the queue limit. */
  void send(ByteBuffer data) {
    Session s = session;
    int size = data.remaining();
    if (s != null && admitSend(size)) {
      s.sendBinary(data, sent(size));
    }
  }

  private boolean admitSend(int size) {
    long waiting = queued.get();
    // A message larger than the whole limit still goes to a client that has nothing waiting.
    if (waiting > 0 && waiting + size > hub.options().maxQueuedBytes()) {
      hub.counters().messagesDropped.increment();
      long now = System.nanoTime();
      long since = fullSince;
      if (since < 0) {
        fullSince = now;
      } else if (now - since > hub.options().slowClientMillis() * 1_000_000L) {
        fullSince = Long.MAX_VALUE / 2; // once
        hub.counters().slowClientsClosed.increment();
        LOG.warn("web client {} does not read: disconnecting it", remote);
        Session s = session;
        if (s != null) {
          s.disconnect();
        }
      }
      return false;
    }
    fullSince = -1;
    queued.addAndGet(size);
    return true;
  }

  private Callback sent(int size) {
    return Callback.from(
        () -> {
          queued.addAndGet(-size);
          hub.counters().messagesSent.increment();
          hub.counters().bytesSent.add(size);
        },
        failure -> queued.addAndGet(-size));
  }

  /** Closes the connection with a status. */
  void close(int code, String reason) {
    Session s = session;
    if (s != null) {
      s.close(code, reason, Callback.NOOP);
    }
  }

  /** Bytes waiting to be sent to this client. */
  long queuedBytes() {
    return queued.get();
  }

  @Override
  public String toString() {
    return "web client " + remote;
  }
}
