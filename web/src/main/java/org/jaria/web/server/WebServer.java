package org.jaria.web.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import org.eclipse.jetty.http.HttpStatus;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import org.eclipse.jetty.websocket.api.StatusCode;
import org.eclipse.jetty.websocket.server.ServerUpgradeRequest;
import org.eclipse.jetty.websocket.server.ServerUpgradeResponse;
import org.eclipse.jetty.websocket.server.WebSocketUpgradeHandler;
import org.jaria.web.control.ControlCommand;
import org.jaria.web.control.Controls;
import org.jaria.web.foxglove.Channel;
import org.jaria.web.foxglove.ChannelTable;
import org.jaria.web.foxglove.ClientRequest;
import org.jaria.web.foxglove.ClientSession;
import org.jaria.web.foxglove.Message;
import org.jaria.web.foxglove.ServerMessages;
import org.jaria.web.source.FrameSource;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The web view's server: one port that serves the page over HTTP and speaks Foxglove's WebSocket
 * protocol ({@code foxglove.websocket.v1}) on {@code /}, so the page, Foxglove and Lichtblick all
 * connect to the same address. A publisher thread takes frames from a {@link FrameSource} at the
 * frame rate and sends each subscriber its channels; a viewer's control commands go to the {@link
 * Controls} when the options allow control.
 *
 * <pre>{@code
 * try (WebServer web = WebServer.start(WebOptions.loopback(0), source, Controls.NONE)) {
 *   System.out.println("Open " + web.url());
 *   ...
 * }
 * }</pre>
 */
public final class WebServer implements AutoCloseable {

  private static final Logger LOG = LoggerFactory.getLogger(WebServer.class);

  private final WebOptions options;
  private final Controls controls;
  private final Counters counters = new Counters();
  private final List<ClientConnection> clients = new CopyOnWriteArrayList<>();
  private final List<MessageSink> sinks = new CopyOnWriteArrayList<>();
  private final Server jetty;
  private final ServerConnector connector;
  private final ScheduledExecutorService publisherThread;
  private final Publisher publisher;
  // The clock the flood limit counts its allowance on: System.nanoTime, or a test's frozen clock.
  private final LongSupplier floodClock;
  private volatile FrameObserver frameObserver;
  private volatile ScheduledFuture<?> publishing;

  @GuardedBy("this")
  private List<Channel> channels = List.of();

  @GuardedBy("this")
  private Message mapMessage;

  @GuardedBy("this")
  private boolean closed;

  private WebServer(
      WebOptions options, FrameSource source, Controls controls, LongSupplier floodClock) {
    this.options = options;
    this.floodClock = floodClock;
    this.controls = options.allowControl() ? controls : Controls.NONE;
    QueuedThreadPool pool = new QueuedThreadPool(16, 2);
    pool.setName("web-server");
    pool.setDaemon(true);
    jetty = new Server(pool);
    org.eclipse.jetty.server.HttpConfiguration http =
        new org.eclipse.jetty.server.HttpConfiguration();
    http.setSendServerVersion(false);
    connector =
        new ServerConnector(jetty, 1, 1, new org.eclipse.jetty.server.HttpConnectionFactory(http));
    connector.setHost(options.bind());
    connector.setPort(options.port());
    connector.setIdleTimeout(30_000);
    jetty.addConnector(connector);
    WebSocketUpgradeHandler ws =
        WebSocketUpgradeHandler.from(
            jetty,
            container -> {
              container.setMaxTextMessageSize(options.maxMessageBytes());
              container.setMaxBinaryMessageSize(options.maxMessageBytes());
              container.setMaxFrameSize(options.maxMessageBytes());
              container.setIdleTimeout(Duration.ofMinutes(2));
              container.addMapping("/", this::upgrade);
            });
    ws.setHandler(new StaticFiles(this));
    jetty.setHandler(ws);
    publisher = new Publisher(source, this);
    publisherThread =
        Executors.newSingleThreadScheduledExecutor(
            r -> {
              Thread t = new Thread(r, "web-publisher");
              t.setDaemon(true);
              return t;
            });
  }

  /**
   * Starts serving.
   *
   * @param controls what viewers may control (used only if {@code options.allowControl()})
   * @throws IOException if the port cannot be opened (in use, or an address not of this computer)
   */
  public static WebServer start(WebOptions options, FrameSource source, Controls controls)
      throws IOException {
    return start(options, source, controls, System::nanoTime);
  }

  /**
   * {@link #start(WebOptions, FrameSource, Controls)} with the flood limit on {@code floodClock}.
   */
  static WebServer start(
      WebOptions options, FrameSource source, Controls controls, LongSupplier floodClock)
      throws IOException {
    WebServer s = new WebServer(options, source, controls, floodClock);
    try {
      s.jetty.start();
    } catch (Exception e) {
      s.close();
      throw new IOException(
          "cannot serve the web view on "
              + options.bind()
              + ":"
              + options.port()
              + " ("
              + e.getMessage()
              + "): give another port (--web PORT, 0 for any free one)",
          e);
    }
    long period = Math.round(1e9 / options.rateHz());
    s.publishing =
        s.publisherThread.scheduleAtFixedRate(s::publishSafely, 0, period, TimeUnit.NANOSECONDS);
    return s;
  }

  private void publishSafely() {
    try {
      publisher.step();
    } catch (RuntimeException e) {
      // A frame that fails (a source mid-change) must not end the publisher: the next one follows.
      LOG.warn("web view: a frame failed: {}", e.toString());
    }
  }

  /** The port it listens on. */
  public int port() {
    return connector.getLocalPort();
  }

  /** The options it runs with. */
  public WebOptions options() {
    return options;
  }

  /** The page's address (with the token, if there is one). */
  public URI url() {
    String host = options.bind().contains(":") ? "[" + options.bind() + "]" : options.bind();
    if (host.equals("0.0.0.0")) {
      host = "HOST";
    }
    return URI.create(
        "http://"
            + host
            + ":"
            + port()
            + "/"
            + (options.token() == null ? "" : "?token=" + options.token()));
  }

  /** The WebSocket address for Foxglove or Lichtblick. */
  public URI websocketUrl() {
    return URI.create(url().toString().replaceFirst("^http", "ws"));
  }

  /** What it has done so far. */
  public WebStats stats() {
    return counters.snapshot(clients.size());
  }

  /** Adds a sink (a recording) that gets every message from now on. */
  public void addSink(MessageSink sink) {
    sinks.add(sink);
  }

  /**
   * For benchmarks: called on the publisher thread as each frame is taken from the source, before
   * it is sent, with the frame's time stamp and the {@link System#nanoTime()} of that moment.
   */
  public void setFrameObserver(FrameObserver observer) {
    frameObserver = observer;
  }

  /** Told of each frame published (benchmarks). */
  @FunctionalInterface
  public interface FrameObserver {
    /**
     * A frame was taken and is about to be sent.
     *
     * @param frameTime the frame's time stamp (the source's clock), ns
     * @param sampledNanos {@link System#nanoTime()} when the frame was taken from the source
     */
    void published(long frameTime, long sampledNanos);
  }

  // ---- used by the connections and the publisher ----

  Counters counters() {
    return counters;
  }

  List<ClientConnection> clientList() {
    return clients;
  }

  List<MessageSink> sinkList() {
    return sinks;
  }

  void frameTaken(long frameTime, long sampledNanos) {
    FrameObserver o = frameObserver;
    if (o != null) {
      o.published(frameTime, sampledNanos);
    }
  }

  /** Whether {@code given} is the token (always, when there is none). */
  boolean tokenOk(String given) {
    String token = options.token();
    return token == null
        || (given != null
            && MessageDigest.isEqual(
                token.getBytes(StandardCharsets.UTF_8), given.getBytes(StandardCharsets.UTF_8)));
  }

  /** Decides a WebSocket upgrade: the protocol, the token and the client limit. */
  private Object upgrade(ServerUpgradeRequest req, ServerUpgradeResponse resp, Callback callback) {
    String token = Request.extractQueryParameters(req).getValue("token");
    String refusal = null;
    int status = HttpStatus.BAD_REQUEST_400;
    if (!req.getSubProtocols().contains(ServerMessages.SUBPROTOCOL)) {
      refusal = "this server speaks the WebSocket subprotocol " + ServerMessages.SUBPROTOCOL;
    } else if (!tokenOk(token)) {
      refusal = "the address needs its token: open the address the server printed";
      status = HttpStatus.FORBIDDEN_403;
    } else if (clients.size() >= options.maxClients()) {
      refusal = "too many viewers (at most " + options.maxClients() + ")";
      status = HttpStatus.SERVICE_UNAVAILABLE_503;
    }
    if (refusal != null) {
      counters.clientsRefused.increment();
      Response.writeError(req, resp, callback, status, refusal);
      return null;
    }
    resp.setAcceptedSubProtocol(ServerMessages.SUBPROTOCOL);
    // Control goes to clients from the page's own origin, from programs (no Origin), or that know
    // the token; another web site open in the same browser may watch but not drive.
    String origin = req.getHeaders().get("Origin");
    boolean trusted = origin == null || sameOrigin(origin, req) || options.token() != null;
    return new ClientConnection(
        this,
        options.allowControl() && trusted,
        String.valueOf(req.getConnectionMetaData().getRemoteSocketAddress()));
  }

  private static boolean sameOrigin(String origin, ServerUpgradeRequest req) {
    String host = req.getHeaders().get("Host");
    return host != null && (origin.equals("http://" + host) || origin.equals("https://" + host));
  }

  long floodNanos() {
    return floodClock.getAsLong();
  }

  synchronized void opened(ClientConnection c) {
    if (closed) {
      c.close(StatusCode.SHUTDOWN, "the server is stopping");
      return;
    }
    clients.add(c);
    counters.clientsServed.increment();
    List<String> capabilities = new ArrayList<>();
    if (options.allowControl() && controls.describe().length() > 0) {
      capabilities.add("clientPublish");
    }
    c.sendText(
        ServerMessages.serverInfo(
            options.serverName(),
            capabilities,
            Map.of(
                "jaria.control",
                options.allowControl() ? controls.describe() : "",
                "jaria.drive.hold.ms",
                String.valueOf(ControlCommand.DRIVE_HOLD_MILLIS)),
            Long.toHexString(System.identityHashCode(this))));
    if (!channels.isEmpty()) {
      c.sendText(ServerMessages.advertise(channels));
    }
  }

  void closed(ClientConnection c) {
    clients.remove(c);
  }

  /** From the publisher: channels changed (and maybe the map). */
  synchronized void channelsChanged(List<Channel> all, ChannelTable.Change change, Message map) {
    channels = all;
    if (map != null) {
      mapMessage = map;
    }
    for (ClientConnection c : clients) {
      if (!change.removed().isEmpty()) {
        c.state().channelsRemoved(change.removed());
        c.sendText(ServerMessages.unadvertise(change.removed()));
      }
      if (!change.added().isEmpty()) {
        c.sendText(ServerMessages.advertise(change.added()));
      }
    }
  }

  private synchronized List<Channel> channels() {
    return channels;
  }

  private synchronized Message latchedMap() {
    return mapMessage;
  }

  /** A client's request, admitted by the flood limit. */
  void handle(ClientConnection c, ClientRequest request, int size) {
    ClientSession.Outcome o = c.state().handle(request, channels());
    if (o.problem() != null) {
      switch (o.problem()) {
        case MALFORMED -> counters.malformed.increment();
        case UNKNOWN_OP -> counters.unknownOps.increment();
        case REFUSED, FLOOD -> counters.refused.increment();
      }
    }
    o.replies().forEach(c::sendText);
    Message map = latchedMap();
    if (map != null) {
      for (Long channelId : o.subscribed()) {
        for (Channel ch : channels()) {
          if (ch.id() == channelId && ch.topic().equals(map.topic())) {
            long sub = c.state().subscriptionFor(channelId);
            c.send(ServerMessages.messageData((int) sub, map.timeNanos(), map.payload()));
          }
        }
      }
    }
    if (o.published() != null) {
      control(c, o.published());
    }
  }

  private void control(ClientConnection c, ClientSession.Published p) {
    String problem;
    try {
      problem = ControlCommand.apply(ControlCommand.parse(p.topic(), p.payload()), controls);
    } catch (IllegalArgumentException | IllegalStateException e) {
      problem = e.getMessage();
    }
    if (problem == null) {
      counters.controlCommands.increment();
    } else {
      counters.refused.increment();
      c.sendText(ServerMessages.status(ServerMessages.Level.WARNING, problem));
    }
  }

  /** Stops the publisher, disconnects every client, closes the port and the sinks. */
  @Override
  public void close() {
    synchronized (this) {
      if (closed) {
        return;
      }
      closed = true;
    }
    ScheduledFuture<?> p = publishing;
    if (p != null) {
      p.cancel(false);
    }
    publisherThread.shutdown();
    try {
      if (!publisherThread.awaitTermination(5, TimeUnit.SECONDS)) {
        LOG.warn("web view: the publisher did not stop within 5 s");
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    for (ClientConnection c : clients) {
      c.close(StatusCode.SHUTDOWN, "the server is stopping");
    }
    try {
      jetty.stop();
    } catch (Exception e) {
      LOG.warn("web view: stopping the server: {}", e.toString());
    }
    for (MessageSink s : sinks) {
      s.close();
    }
  }
}
