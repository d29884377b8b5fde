package org.jaria.net.server;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.LoginDigest;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.protocol.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Understands the packets a client sends, on the I/O thread: the introduction and login, then
 * requests (once, at an interval, stop) and the fixed commands. Decoding is strict — a login packet
 * that is not what ArNetworking sends closes that client — while a request for something missing or
 * not allowed is only logged and counted, as ArNetworking does. Requests are handed to workers or
 * to the robot's cycle; nothing slow happens here.
 */
final class Dispatcher {

  private static final Logger log = LoggerFactory.getLogger(Dispatcher.class);

  /** Longest user name kept (ARIA reads at most 511 bytes). */
  private static final int MAX_NAME = 64;

  private final ArServerBase server;
  private final ServerOptions options;

  Dispatcher(ArServerBase server, ServerOptions options) {
    this.server = server;
    this.options = options;
  }

  /** The server's introduction, sent as soon as a client connects. */
  ArNetPacket introduction(ArServerClient c, int udpPort) {
    ArNetPacket p = new ArNetPacket(Protocol.SERVER_INTRODUCTION);
    p.strToBuf(Protocol.SERVER_VERSION)
        .uByte2ToBuf(udpPort)
        .uByte4ToBuf(c.authKey)
        .uByte4ToBuf(c.introKey & 0xFFFFFFFFL)
        .strToBuf(c.passwordKey)
        .strToBuf(options.protocolVersion());
    return p;
  }

  /** Handles one packet from {@code c} (TCP, or UDP when {@code udp}). */
  void onPacket(ArServerClient c, ArNetPacket p, boolean udp) throws ProtocolException {
    if (c.closeAfterFlush || c.isClosed()) {
      return;
    }
    int cmd = p.getCommand();
    try {
      if (c.state() == ArServerClient.State.SENT_INTRO) {
        if (cmd == Protocol.CLIENT_INTRODUCTION) {
          introduction(c, p);
        } else if (cmd == Protocol.CLIENT_TCP_ONLY || cmd == Protocol.CLIENT_UDP_CONFIRMATION) {
          // Harmless before login (ARIA clients may send TCP_ONLY right after their intro).
          c.tcpOnly = true;
        } else if (cmd == Protocol.CLIENT_SHUTDOWN) {
          bye(c);
        } else {
          throw new ProtocolException(
              NetError.PROTOCOL, "sent command " + cmd + " before its introduction");
        }
        return;
      }
      switch (cmd) {
        case Protocol.CLIENT_SHUTDOWN -> bye(c);
        case Protocol.CLIENT_INTRODUCTION ->
            log.debug("{}: a second introduction, ignored (as ArNetworking does)", c);
        case Protocol.CLIENT_TCP_ONLY, Protocol.CLIENT_UDP_INTRODUCTION -> c.tcpOnly = true;
        case Protocol.CLIENT_UDP_CONFIRMATION -> {
          // The client heard our UDP introduction; nothing else to do.
        }
        case Protocol.CLIENT_LIST -> sendList(c);
        case Protocol.CLIENT_REQUEST -> request(c, p);
        case Protocol.CLIENT_REQUEST_STOP -> {
          int command = p.bufToUByte2();
          if (c.requests.remove(command) == null) {
            log.debug("{}: stop for command {} it had not requested", c, command);
          }
        }
        default -> requestOnce(c, p);
      }
    } catch (ArNetPacketException e) {
      if (c.state() == ArServerClient.State.SENT_INTRO) {
        throw new ProtocolException(NetError.MALFORMED, "malformed introduction: " + e, e);
      }
      server.stats.requestErrors.increment();
      log.info("{}: malformed packet for command {}: {}", c, cmd, e.getMessage());
    }
  }

  private void bye(ArServerClient c) {
    c.setCloseReason("the client said goodbye");
    c.closeAfterFlush = true;
    server.io().scheduleWrite(c, false);
  }

  private static String name(String s) {
    return s.length() > MAX_NAME ? s.substring(0, MAX_NAME) : s;
  }

  private void introduction(ArServerClient c, ArNetPacket p) {
    int clientUdpPort = p.bufToUByte2();
    String user = name(p.bufToStr());
    byte[] digest = p.bufToData(LoginDigest.DIGEST_BYTES);
    String protocolVersion = p.bufToStr();
    // The client's type byte (real/simulated) follows; JAria enforces no type.
    if (!options.protocolVersion().isEmpty()
        && !options.protocolVersion().equals(protocolVersion)
        && !Protocol.JARIA_ACK_VERSION.equals(protocolVersion)) {
      reject(
          c,
          Protocol.REJECTED_SERVER_PROTOCOL,
          "Server rejecting client connection since protocol version does not match");
      return;
    }
    if (server.getNumClients() >= options.maxClients()) {
      server.stats.refusedFull.increment();
      reject(
          c,
          Protocol.REJECTED_TOO_MANY_CLIENTS,
          "Server rejecting connection since it would exceed the maximum number of allowed"
              + " connections (which is "
              + options.maxClients()
              + ")");
      return;
    }
    Authenticator auth = options.authenticator();
    Credentials creds;
    if (auth.isOpen()) {
      creds = auth.find(user).orElseThrow();
    } else {
      switch (server.loginLimiter().tryCheck(c.getIpString())) {
        case ADDRESS_THROTTLED -> {
          server.stats.loginThrottled.increment();
          log.info("{}: too many failed logins from this address; refused without checking", c);
          reject(
              c,
              Protocol.REJECTED_BAD_LOGIN,
              "too many failed logins from this address; wait a minute before trying again");
          return;
        }
        case BUSY -> {
          server.stats.loginBusy.increment();
          log.info("{}: too many password checks over all addresses; refused without checking", c);
          reject(
              c,
              Protocol.REJECTED_BAD_LOGIN,
              "the server is checking too many passwords; try again in a few seconds");
          return;
        }
        case CHECK -> {
          // Checked below.
        }
      }
      Optional<Credentials> found = auth.find(user);
      byte[] want =
          LoginDigest.digest(
              options.serverKey(),
              c.passwordKey,
              found.map(Credentials::getPassword).orElse("\u0000no such user"));
      if (found.isEmpty() || !LoginDigest.matches(want, digest)) {
        server.stats.loginFailed.increment();
        server.loginLimiter().failed(c.getIpString());
        log.info("{}: rejected user '{}' or password", c, user);
        reject(c, Protocol.REJECTED_BAD_LOGIN, "");
        return;
      }
      creds = found.get();
    }
    c.wantsAcks = Protocol.JARIA_ACK_VERSION.equals(protocolVersion);
    server.loginLimiter().succeeded(c.getIpString());
    c.loggedIn(creds);
    c.tcpOnly = clientUdpPort == 0 || server.udpPort() == 0 || c.tcpOnly;
    server.sendPacket(c, new ArNetPacket(Protocol.SERVER_CONNECTED));
    sendList(c);
    log.info("{} logged in{}", c, user.isEmpty() ? "" : " as '" + user + "'");
    server.clientLoggedIn(c);
  }

  private void reject(ArServerClient c, int reason, String text) {
    c.setCloseReason("rejected (" + reason + "): " + (text.isEmpty() ? "bad login" : text));
    ArNetPacket r = new ArNetPacket(Protocol.SERVER_REJECTED);
    r.byte2ToBuf(reason).strToBuf(text);
    server.sendPacket(c, r);
    c.closeAfterFlush = true;
  }

  /** Sends the data list the user may see: LIST, LISTARGRET, LISTGROUPANDFLAGS (split to fit). */
  void sendList(ArServerClient c) {
    List<DataInfo> visible = new ArrayList<>();
    for (DataInfo d : server.dataList()) {
      if (c.hasGroupAccess(d.commandGroup())) {
        visible.add(d);
      }
    }
    for (ArNetPacket p : listPackets(visible)) {
      server.sendPacket(c, p);
    }
  }

  /** The three kinds of list packets for {@code list}, each kind split so a packet fits. */
  static List<ArNetPacket> listPackets(List<DataInfo> list) {
    List<ArNetPacket> out = new ArrayList<>();
    addList(out, list, Protocol.SERVER_LIST, d -> new String[] {d.name(), d.description()});
    addList(
        out,
        list,
        Protocol.SERVER_LIST_ARGRET,
        d -> new String[] {d.argumentDescription(), d.returnDescription()});
    addList(
        out,
        list,
        Protocol.SERVER_LIST_GROUP_AND_FLAGS,
        d -> new String[] {d.commandGroup(), d.dataFlags()});
    return out;
  }

  private static void addList(
      List<ArNetPacket> out,
      List<DataInfo> list,
      int command,
      java.util.function.Function<DataInfo, String[]> fields) {
    int i = 0;
    do {
      ArNetPacket body = new ArNetPacket(command);
      int count = 0;
      int size = 2;
      while (i < list.size()) {
        String[] f = fields.apply(list.get(i));
        int need = 2 + f[0].length() * 3 + 1 + f[1].length() * 3 + 1;
        if (count > 0 && size + need > ArNetPacket.MAX_DATA_LENGTH) {
          break;
        }
        size += need;
        count++;
        i++;
      }
      body.uByte2ToBuf(count);
      for (int k = i - count; k < i; k++) {
        String[] f = fields.apply(list.get(k));
        body.uByte2ToBuf(list.get(k).id()).strToBuf(clip(f[0])).strToBuf(clip(f[1]));
      }
      out.add(body);
    } while (i < list.size());
  }

  /** ARIA's client reads descriptions into buffers of 512-1024 bytes: keep them shorter. */
  private static String clip(String s) {
    return s.length() > 500 ? s.substring(0, 500) : s;
  }

  private void request(ArServerClient c, ArNetPacket p) {
    int command = p.bufToUByte2();
    long ms = p.bufToByte4();
    byte[] args = p.remainingBytes();
    try {
      dispatchRequest(c, command, ms, args);
    } finally {
      server.stats.requests.increment();
    }
  }

  private void dispatchRequest(ArServerClient c, int command, long ms, byte[] args) {
    DataEntry e = server.entry(command);
    if (e == null) {
      server.stats.requestErrors.increment();
      log.info("{}: request for command {}, which does not exist", c, command);
      return;
    }
    if (!c.hasGroupAccess(e.info.commandGroup())) {
      server.stats.requestErrors.increment();
      log.info("{}: may not request '{}' ({} group)", c, e.name(), e.info.commandGroup());
      return;
    }
    if (!c.requests.containsKey(command) && c.requests.size() >= options.maxSubscriptions()) {
      server.stats.requestErrors.increment();
      server.requestFailed(
          c,
          e,
          NetError.TOO_MANY_SUBSCRIPTIONS,
          "at most " + options.maxSubscriptions() + " requests per client");
      return;
    }
    long intervalNanos =
        ms < 0 ? -1 : TimeUnit.MILLISECONDS.toNanos(Math.max(ms, options.minInterval().toMillis()));
    ArServerClient.Request r = new ArServerClient.Request(e, intervalNanos, args);
    r.nextDueNanos = System.nanoTime() + Math.max(0, intervalNanos);
    c.requests.put(command, r);
    // ArNetworking answers a new request at once, then at the interval (or on broadcasts).
    if (e.publication != null) {
      DataEntry.Encoded enc = e.currentEncoded();
      if (enc != null) {
        r.lastVersion = enc.version();
        c.out.offerUpdate(Outgoing.update(command, enc.version(), enc.wire()));
        server.io().scheduleWrite(c, false);
      }
    } else if (r.running.compareAndSet(false, true)) {
      if (c.pendingCalls.incrementAndGet() > options.maxPendingCalls()) {
        c.pendingCalls.decrementAndGet();
        r.running.set(false);
        server.stats.busy.increment();
        return;
      }
      server.execute(c, e, args, r);
    }
    server.publisher().wakeup();
  }

  private void requestOnce(ArServerClient c, ArNetPacket p) {
    try {
      dispatchOnce(c, p);
    } finally {
      // Counted once handed on (queued, refused or failed), so a count that includes a request
      // means its work is already where it will run.
      server.stats.requests.increment();
    }
  }

  private void dispatchOnce(ArServerClient c, ArNetPacket p) {
    int command = p.getCommand();
    DataEntry e = server.entry(command);
    if (e == null) {
      server.stats.requestErrors.increment();
      log.info("{}: asked for command {}, which does not exist", c, command);
      return;
    }
    if (!c.hasGroupAccess(e.info.commandGroup())) {
      server.stats.requestErrors.increment();
      log.info("{}: may not use '{}' ({} group)", c, e.name(), e.info.commandGroup());
      return;
    }
    CallPolicy policy = e.policy;
    if (policy != CallPolicy.QUEUED && server.onCycle(e)) {
      // A stop is never refused, and a joystick's flood collapses to its newest position.
      server.executeCoalesced(c, e, p.remainingBytes(), policy);
      return;
    }
    if (policy == CallPolicy.SAFETY) {
      // Off the cycle a stop still waits for a worker, but never for this client's other requests.
      c.pendingCalls.incrementAndGet();
    } else if (c.pendingCalls.incrementAndGet() > options.maxPendingCalls()) {
      c.pendingCalls.decrementAndGet();
      server.stats.busy.increment();
      server.requestFailed(
          c,
          e,
          NetError.BUSY,
          "more than " + options.maxPendingCalls() + " requests waiting; wait for replies");
      return;
    }
    server.execute(c, e, p.remainingBytes(), null);
  }
}
