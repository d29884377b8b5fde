package org.jaria.net.server;

import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Frames;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.PasswordHash;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.protocol.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Understands the frames a client sends, on the I/O thread: the login conversation, then requests,
 * subscriptions and pings. Decoding is strict — a frame that is not what its kind promises closes
 * that client — while a well-formed request for something missing or not allowed only gets an error
 * reply. Requests are handed to workers or to the robot's cycle; nothing slow happens here.
 */
final class Dispatcher {

  private static final Logger log = LoggerFactory.getLogger(Dispatcher.class);

  /** Longest client name or user name kept. */
  private static final int MAX_NAME = 64;

  private final ArServerBase server;
  private final ServerOptions options;

  Dispatcher(ArServerBase server, ServerOptions options) {
    this.server = server;
    this.options = options;
  }

  /** Handles one frame of {@code len} bytes at {@code off} of {@code a}. */
  void onFrame(ArServerClient c, byte[] a, int off, int len) throws ProtocolException {
    if (c.closeAfterFlush) {
      return;
    }
    ArNetPacket p = ArNetPacket.wrap(a, off, len);
    try {
      Kind kind = Kind.fromCode(p.bufToLong());
      if (kind == null) {
        throw new ProtocolException(NetError.MALFORMED, "unknown frame kind");
      }
      switch (c.state()) {
        case AWAITING_HELLO -> {
          expect(kind, Kind.HELLO);
          hello(c, p);
        }
        case AWAITING_LOGIN -> {
          expect(kind, Kind.LOGIN);
          login(c, p);
        }
        case READY -> ready(c, kind, p);
        case CLOSED -> {
          // Frames after close are ignored.
        }
      }
      if (kind != Kind.CALL && p.hasMore()) {
        // Later versions may append values to a message, but they must be well-formed.
        p.validate();
      }
    } catch (ArNetPacketException e) {
      throw new ProtocolException(NetError.MALFORMED, "malformed frame: " + e.getMessage(), e);
    }
  }

  private static void expect(Kind got, Kind wanted) throws ProtocolException {
    if (got != wanted) {
      throw new ProtocolException(
          NetError.PROTOCOL, "sent " + got + " where " + wanted + " was expected");
    }
  }

  private static String name(String s) {
    if (s == null) {
      return "";
    }
    return s.length() > MAX_NAME ? s.substring(0, MAX_NAME) : s;
  }

  private void hello(ArServerClient c, ArNetPacket p) throws ProtocolException {
    String magic = p.bufToStr();
    if (!Protocol.MAGIC.equals(magic)) {
      throw new ProtocolException(NetError.MALFORMED, "not a JAria client (bad magic)");
    }
    long version = p.bufToLong();
    String clientName = name(p.bufToStr());
    String user = name(p.bufToStr());
    c.setClientName(clientName);
    if (version != Protocol.VERSION) {
      refuse(
          c,
          NetError.BAD_VERSION,
          "the server speaks protocol version "
              + Protocol.VERSION
              + " and the client "
              + version
              + ": use a client and server of the same JAria release");
      return;
    }
    Authenticator auth = options.authenticator();
    c.nonce = PasswordHash.randomBytes(server.random, Protocol.NONCE_BYTES);
    byte[] salt;
    int iterations;
    Optional<Credentials> creds = auth.find(user);
    if (auth.isOpen()) {
      salt = new byte[0];
      iterations = 0;
      c.pendingCredentials = creds.orElseThrow();
    } else if (creds.isPresent()) {
      salt = creds.get().getSalt();
      iterations = creds.get().getIterations();
      c.pendingCredentials = creds.get();
    } else {
      // An unknown user gets a believable challenge, so names cannot be probed.
      salt = Arrays.copyOf(PasswordHash.proof(server.serverKey, user.getBytes(UTF8)), 16);
      iterations = PasswordHash.DEFAULT_ITERATIONS;
      c.pendingCredentials = null;
    }
    c.setState(ArServerClient.State.AWAITING_LOGIN);
    server.sendFrame(
        c,
        Frames.frame(
            Kind.CHALLENGE,
            ArNetPacket.of(
                Protocol.MAGIC, Protocol.VERSION, options.serverName(), c.nonce, salt, iterations)),
        false);
  }

  private static final java.nio.charset.Charset UTF8 = java.nio.charset.StandardCharsets.UTF_8;

  private void login(ArServerClient c, ArNetPacket p) throws ProtocolException {
    byte[] proof = p.bufToData();
    Credentials creds = c.pendingCredentials;
    boolean ok =
        creds != null
            && (options.authenticator().isOpen()
                || PasswordHash.matches(PasswordHash.proof(creds.getKey(), c.nonce), proof));
    c.pendingCredentials = null;
    c.nonce = null;
    if (!ok) {
      server.stats.loginFailed.increment();
      log.info("{}: login refused", c);
      refuse(c, NetError.BAD_LOGIN, "login refused: wrong user name or password");
      return;
    }
    c.loggedIn(c.getClientName(), creds);
    List<DataInfo> visible =
        server.dataList().stream().filter(d -> creds.hasGroupAccess(d.commandGroup())).toList();
    ArNetPacket w = new ArNetPacket();
    w.intToBuf(c.getId())
        .intToBuf(options.minInterval().toMillis())
        .intToBuf(options.maxInboundFrame())
        .arrayToBuf(visible.size());
    for (DataInfo d : visible) {
      d.write(w);
    }
    server.sendFrame(c, Frames.frame(Kind.WELCOME, w), false);
    log.info("{} logged in as '{}' ({})", c, c.getUser(), c.getClientName());
    server.clientLoggedIn(c);
  }

  private void refuse(ArServerClient c, NetError code, String reason) {
    c.setCloseReason(reason);
    server.sendFrame(c, Frames.frame(Kind.REFUSED, code.code(), reason), false);
    c.closeAfterFlush = true;
  }

  private void ready(ArServerClient c, Kind kind, ArNetPacket p) throws ProtocolException {
    switch (kind) {
      case CALL -> call(c, p);
      case SUBSCRIBE -> subscribe(c, p);
      case UNSUBSCRIBE -> {
        int dataId = p.bufToInt();
        c.subscriptions.remove(dataId);
      }
      case PING -> {
        long token = p.bufToLong();
        server.sendFrame(c, Frames.frame(Kind.PONG, token), false);
      }
      case BYE -> {
        c.setCloseReason("the client said goodbye");
        c.closeAfterFlush = true;
        server.io().scheduleWrite(c, false);
      }
      default ->
          throw new ProtocolException(NetError.PROTOCOL, "sent " + kind + " after logging in");
    }
  }

  private void call(ArServerClient c, ArNetPacket p) {
    int reqId = p.bufToInt();
    int dataId = p.bufToInt();
    // The arguments must be well-formed MessagePack; what they mean is the handler's business.
    p.validate();
    server.stats.requests.increment();
    DataEntry e = server.entry(dataId);
    if (e == null) {
      server.sendError(c, reqId, dataId, NetError.UNKNOWN_DATA, "no data with id " + dataId);
      return;
    }
    if (!c.hasGroupAccess(e.info.commandGroup())) {
      server.sendError(
          c,
          reqId,
          dataId,
          NetError.NOT_ALLOWED,
          "user '" + c.getUser() + "' may not use " + e.info.commandGroup() + " data");
      return;
    }
    if (c.pendingCalls.incrementAndGet() > options.maxPendingCalls()) {
      c.pendingCalls.decrementAndGet();
      server.stats.busy.increment();
      server.sendError(
          c,
          reqId,
          dataId,
          NetError.BUSY,
          "more than " + options.maxPendingCalls() + " requests waiting; wait for replies");
      return;
    }
    int start = p.getReadLength();
    byte[] args = p.toByteArray();
    byte[] argBytes = Arrays.copyOfRange(args, start, args.length);
    server.execute(c, reqId, e, argBytes);
  }

  private void subscribe(ArServerClient c, ArNetPacket p) {
    int reqId = p.bufToInt();
    int dataId = p.bufToInt();
    long intervalMs = p.bufToLong();
    DataEntry e = server.entry(dataId);
    if (e == null) {
      server.sendError(c, reqId, dataId, NetError.UNKNOWN_DATA, "no data with id " + dataId);
      return;
    }
    if (e.publication == null) {
      server.sendError(
          c,
          reqId,
          dataId,
          NetError.NOT_SUBSCRIBABLE,
          e.name() + " is a request, not published data: ask for it with a call");
      return;
    }
    if (!c.hasGroupAccess(e.info.commandGroup())) {
      server.sendError(
          c,
          reqId,
          dataId,
          NetError.NOT_ALLOWED,
          "user '" + c.getUser() + "' may not use " + e.info.commandGroup() + " data");
      return;
    }
    if (!c.subscriptions.containsKey(dataId)
        && c.subscriptions.size() >= options.maxSubscriptions()) {
      server.sendError(
          c,
          reqId,
          dataId,
          NetError.TOO_MANY_SUBSCRIPTIONS,
          "at most " + options.maxSubscriptions() + " subscriptions per client");
      return;
    }
    long minMs = options.minInterval().toMillis();
    long granted = Math.max(intervalMs, minMs);
    ArServerClient.Subscription s =
        new ArServerClient.Subscription(e, TimeUnit.MILLISECONDS.toNanos(granted));
    s.nextDueNanos = System.nanoTime();
    c.subscriptions.put(dataId, s);
    server.sendFrame(c, Frames.frame(Kind.SUBSCRIBED, reqId, dataId, granted), false);
    server.publisher().wakeup();
  }

  /** The payload of a response as a shared read-only buffer. */
  static ByteBuffer shared(byte[] b) {
    return ByteBuffer.wrap(b).asReadOnlyBuffer();
  }
}
