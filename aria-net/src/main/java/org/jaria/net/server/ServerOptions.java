package org.jaria.net.server;

import java.time.Duration;
import org.jaria.clock.Clock;
import org.jaria.net.protocol.Protocol;

/**
 * Settings of an {@link ArServerBase}: where it listens, who may log in and the limits that keep
 * one slow or hostile client from hurting the robot or the other clients. Build with {@link
 * #builder()}; the defaults suit a robot with a handful of monitors.
 *
 * @param serverName sent to clients at login
 * @param port TCP port (0: the system picks a free one; see {@link ArServerBase#getPort()})
 * @param bindAddress address to listen on; null: every interface, or loopback only when the
 *     authenticator is open (anybody could otherwise drive the robot from the network; see
 *     openBeyondLoopback)
 * @param authenticator who may log in
 * @param maxClients most clients logged in at once
 * @param loginTimeout time a new connection has to log in
 * @param idleTimeout a logged-in client that sends nothing for this long is dropped; zero (the
 *     default): never, since ArNetworking clients may rightly listen without sending for hours
 * @param stallTimeout a client with data waiting that accepts no byte for this long is dropped;
 *     zero: never
 * @param maxQueuedBytes most bytes of replies waiting for one client; a reply beyond it drops the
 *     client (subscription updates never count: they are coalesced, newest wins)
 * @param serverKey ArNetworking's server key, mixed into login digests ("" as in ARIA)
 * @param protocolVersion version text clients must announce ("" accepts any)
 * @param maxPendingLogins most connections not logged in yet, over all addresses: beyond it only
 *     the loopback and addresses that have logged in before get in (replacing a waiting one)
 * @param maxPendingLoginsPerAddress most connections not logged in yet from one address; a newer
 *     one from that address replaces its oldest
 * @param maxLoginFailures failed logins per address within the window before it is throttled
 * @param loginFailureWindow the window of maxLoginFailures
 * @param maxLoginChecksPerSecond password checks per second over all addresses (addresses that
 *     logged in before are not counted; addresses that failed get half)
 * @param openBeyondLoopback whether an open server (no login) may listen beyond the loopback
 *     address: anybody who reaches the port may then drive the robot
 * @param udp whether to open the UDP port for ArNetworking's UDP handshake
 * @param minInterval shortest subscription interval granted (caps the rate)
 * @param maxSubscriptions most subscriptions per client
 * @param maxPendingCalls most requests one client may have waiting to be handled
 * @param workerThreads threads that run request handlers off the robot's cycle
 * @param workerQueue requests waiting for a worker, over all clients
 * @param cycleQueue commands waiting for the robot's cycle, over all clients
 * @param maxCommandsPerCycle most queued commands applied in one robot cycle
 * @param socketSendBuffer SO_SNDBUF of client sockets, bytes (0: the system's default)
 * @param timeoutClock the clock that times login, idle and stall timeouts (a VirtualClock in tests)
 */
public record ServerOptions(
    String serverName,
    int port,
    String bindAddress,
    Authenticator authenticator,
    int maxClients,
    Duration loginTimeout,
    Duration idleTimeout,
    Duration stallTimeout,
    long maxQueuedBytes,
    String serverKey,
    String protocolVersion,
    int maxPendingLogins,
    int maxPendingLoginsPerAddress,
    int maxLoginFailures,
    Duration loginFailureWindow,
    int maxLoginChecksPerSecond,
    boolean openBeyondLoopback,
    boolean udp,
    Duration minInterval,
    int maxSubscriptions,
    int maxPendingCalls,
    int workerThreads,
    int workerQueue,
    int cycleQueue,
    int maxCommandsPerCycle,
    int socketSendBuffer,
    Clock timeoutClock) {

  /** Checks the values. */
  public ServerOptions {
    if (port < 0 || port > 65535) {
      throw new IllegalArgumentException("port must be 0..65535, was " + port);
    }
    if (authenticator == null || timeoutClock == null || serverName == null) {
      throw new IllegalArgumentException("authenticator, clock and server name must be set");
    }
    positive(maxClients, "maxClients");
    positive(maxSubscriptions, "maxSubscriptions");
    positive(maxPendingCalls, "maxPendingCalls");
    positive(workerThreads, "workerThreads");
    positive(workerQueue, "workerQueue");
    positive(cycleQueue, "cycleQueue");
    positive(maxCommandsPerCycle, "maxCommandsPerCycle");
    if (maxQueuedBytes < 4096) {
      throw new IllegalArgumentException("maxQueuedBytes must be at least 4096");
    }
    if (serverKey == null || protocolVersion == null) {
      throw new IllegalArgumentException(
          "server key and protocol version must be set (\"\" for none)");
    }
    positive(maxPendingLogins, "maxPendingLogins");
    positive(maxPendingLoginsPerAddress, "maxPendingLoginsPerAddress");
    positive(maxLoginFailures, "maxLoginFailures");
    positive(maxLoginChecksPerSecond, "maxLoginChecksPerSecond");
    if (loginFailureWindow == null || loginFailureWindow.isNegative()) {
      throw new IllegalArgumentException("the login failure window must be zero or positive");
    }
    for (Duration d : new Duration[] {loginTimeout, idleTimeout, stallTimeout, minInterval}) {
      if (d == null || d.isNegative()) {
        throw new IllegalArgumentException("timeouts and intervals must be zero or positive");
      }
    }
    if (loginTimeout.isZero()) {
      throw new IllegalArgumentException("the login timeout must be positive");
    }
  }

  private static void positive(int v, String name) {
    if (v < 1) {
      throw new IllegalArgumentException(name + " must be at least 1, was " + v);
    }
  }

  /** Defaults: see {@link Builder}. */
  public static ServerOptions defaults() {
    return builder().build();
  }

  /** A builder starting from the defaults. */
  public static Builder builder() {
    return new Builder();
  }

  /** A builder starting from these options. */
  public Builder toBuilder() {
    Builder b = new Builder();
    b.serverName = serverName;
    b.port = port;
    b.bindAddress = bindAddress;
    b.authenticator = authenticator;
    b.maxClients = maxClients;
    b.loginTimeout = loginTimeout;
    b.idleTimeout = idleTimeout;
    b.stallTimeout = stallTimeout;
    b.maxQueuedBytes = maxQueuedBytes;
    b.serverKey = serverKey;
    b.protocolVersion = protocolVersion;
    b.maxPendingLogins = maxPendingLogins;
    b.maxPendingLoginsPerAddress = maxPendingLoginsPerAddress;
    b.maxLoginFailures = maxLoginFailures;
    b.loginFailureWindow = loginFailureWindow;
    b.maxLoginChecksPerSecond = maxLoginChecksPerSecond;
    b.openBeyondLoopback = openBeyondLoopback;
    b.udp = udp;
    b.minInterval = minInterval;
    b.maxSubscriptions = maxSubscriptions;
    b.maxPendingCalls = maxPendingCalls;
    b.workerThreads = workerThreads;
    b.workerQueue = workerQueue;
    b.cycleQueue = cycleQueue;
    b.maxCommandsPerCycle = maxCommandsPerCycle;
    b.socketSendBuffer = socketSendBuffer;
    b.timeoutClock = timeoutClock;
    return b;
  }

  /**
   * Builds {@link ServerOptions}. Defaults: name "jaria", port 7272, open authenticator (on the
   * loopback address only), 32 logged-in clients, 64 not yet logged in (4 per address), 5 s login,
   * no idle timeout, 10 s stall, 1 MiB queued replies, 5 failed logins per address per minute, 20
   * password checks a second, UDP on, 50 ms minimum interval (20 Hz), 64 subscriptions and 16
   * pending requests per client, 2 workers with 256 queued requests, 256 queued cycle commands with
   * 64 applied per cycle.
   */
  public static final class Builder {
    private String serverName = "jaria";
    private int port = Protocol.DEFAULT_PORT;
    private String bindAddress;
    private Authenticator authenticator = Authenticator.open();
    private int maxClients = 32;
    private Duration loginTimeout = Duration.ofSeconds(5);
    private Duration idleTimeout = Duration.ZERO;
    private Duration stallTimeout = Duration.ofSeconds(10);
    private long maxQueuedBytes = 1 << 20;
    private String serverKey = "";
    private String protocolVersion = "";
    private int maxPendingLogins = 64;
    private int maxPendingLoginsPerAddress = 4;
    private int maxLoginFailures = 5;
    private Duration loginFailureWindow = Duration.ofMinutes(1);
    private int maxLoginChecksPerSecond = 20;
    private boolean openBeyondLoopback;
    private boolean udp = true;
    private Duration minInterval = Duration.ofMillis(50);
    private int maxSubscriptions = 64;
    // A MobileEyes-class client asks for everything it shows at once when it connects (JAria's
    // monitor sends some 25 requests); at 16 a loaded server refused part of that as busy.
    private int maxPendingCalls = 64;
    private int workerThreads = 2;
    private int workerQueue = 256;
    private int cycleQueue = 256;
    private int maxCommandsPerCycle = 64;
    private int socketSendBuffer;
    private Clock timeoutClock = Clock.system();

    private Builder() {}

    /** Name sent to clients. */
    public Builder serverName(String v) {
      serverName = v;
      return this;
    }

    /** TCP port; 0 lets the system pick. */
    public Builder port(int v) {
      port = v;
      return this;
    }

    /** Interface address to listen on ("0.0.0.0" for all, "127.0.0.1" for this machine). */
    public Builder bindAddress(String v) {
      bindAddress = v;
      return this;
    }

    /** Who may log in. */
    public Builder authenticator(Authenticator v) {
      authenticator = v;
      return this;
    }

    /** Most clients at once. */
    public Builder maxClients(int v) {
      maxClients = v;
      return this;
    }

    /** Time to log in. */
    public Builder loginTimeout(Duration v) {
      loginTimeout = v;
      return this;
    }

    /** Silence after which a client is dropped (zero: never). */
    public Builder idleTimeout(Duration v) {
      idleTimeout = v;
      return this;
    }

    /** Write stall after which a client is dropped (zero: never). */
    public Builder stallTimeout(Duration v) {
      stallTimeout = v;
      return this;
    }

    /** Most reply bytes waiting for one client. */
    public Builder maxQueuedBytes(long v) {
      maxQueuedBytes = v;
      return this;
    }

    /**
     * ArNetworking's server key: a secret mixed into every login digest, which clients must be
     * given too ("" by default, as in ARIA).
     */
    public Builder serverKey(String v) {
      serverKey = v;
      return this;
    }

    /** A protocol version clients must announce ("" accepts any, as in ARIA). */
    public Builder protocolVersion(String v) {
      protocolVersion = v;
      return this;
    }

    /**
     * Most connections that have not logged in yet, over all addresses. Beyond it a connection from
     * the loopback address or from an address that has logged in before replaces the oldest one
     * waiting (preferably one from elsewhere); any other is closed at once.
     */
    public Builder maxPendingLogins(int v) {
      maxPendingLogins = v;
      return this;
    }

    /**
     * Most connections that have not logged in yet from one address: a newer one from that address
     * replaces its oldest, so sockets that never log in cannot keep the address's users out.
     */
    public Builder maxPendingLoginsPerAddress(int v) {
      maxPendingLoginsPerAddress = v;
      return this;
    }

    /**
     * Password checks per second over all addresses, so guesses from many addresses are as slow as
     * from one. Addresses that have logged in before are not counted; addresses with failed logins
     * may use only half of the budget, leaving the rest to the others.
     */
    public Builder maxLoginChecksPerSecond(int v) {
      maxLoginChecksPerSecond = v;
      return this;
    }

    /**
     * Lets a server without a login listen beyond the loopback address. Off by default: {@link
     * ArServerBase#open()} refuses, since anybody who can reach the port could then drive the
     * robot.
     */
    public Builder openBeyondLoopback(boolean v) {
      openBeyondLoopback = v;
      return this;
    }

    /**
     * Failed logins from one address within {@link #loginFailureWindow} after which its logins are
     * refused unchecked until the window has passed.
     */
    public Builder maxLoginFailures(int v) {
      maxLoginFailures = v;
      return this;
    }

    /** The window of {@link #maxLoginFailures}. */
    public Builder loginFailureWindow(Duration v) {
      loginFailureWindow = v;
      return this;
    }

    /**
     * Whether to open ArNetworking's UDP port (same number as TCP); data is sent over TCP anyway.
     */
    public Builder udp(boolean v) {
      udp = v;
      return this;
    }

    /** Shortest subscription interval. */
    public Builder minInterval(Duration v) {
      minInterval = v;
      return this;
    }

    /** Most subscriptions per client. */
    public Builder maxSubscriptions(int v) {
      maxSubscriptions = v;
      return this;
    }

    /** Most requests one client may have waiting. */
    public Builder maxPendingCalls(int v) {
      maxPendingCalls = v;
      return this;
    }

    /** Handler threads. */
    public Builder workerThreads(int v) {
      workerThreads = v;
      return this;
    }

    /** Requests waiting for a handler thread. */
    public Builder workerQueue(int v) {
      workerQueue = v;
      return this;
    }

    /** Commands waiting for the robot's cycle. */
    public Builder cycleQueue(int v) {
      cycleQueue = v;
      return this;
    }

    /** Commands applied per robot cycle. */
    public Builder maxCommandsPerCycle(int v) {
      maxCommandsPerCycle = v;
      return this;
    }

    /** SO_SNDBUF of client sockets (0: system default). */
    public Builder socketSendBuffer(int v) {
      socketSendBuffer = v;
      return this;
    }

    /** Clock of the login, idle and stall timeouts. */
    public Builder timeoutClock(Clock v) {
      timeoutClock = v;
      return this;
    }

    /** The options. */
    public ServerOptions build() {
      return new ServerOptions(
          serverName,
          port,
          bindAddress,
          authenticator,
          maxClients,
          loginTimeout,
          idleTimeout,
          stallTimeout,
          maxQueuedBytes,
          serverKey,
          protocolVersion,
          maxPendingLogins,
          maxPendingLoginsPerAddress,
          maxLoginFailures,
          loginFailureWindow,
          maxLoginChecksPerSecond,
          openBeyondLoopback,
          udp,
          minInterval,
          maxSubscriptions,
          maxPendingCalls,
          workerThreads,
          workerQueue,
          cycleQueue,
          maxCommandsPerCycle,
          socketSendBuffer,
          timeoutClock);
    }
  }
}
