package org.jaria.robot;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import java.util.function.LongSupplier;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The first stage of the robot: the link to it. Owns the device connection, the queue of packets
 * read from it ({@link PacketIntake}), the connection handshake ({@link Handshake}) and the timeout
 * that notices a lost link, with the callbacks of the connection's life. It hands each packet on to
 * the {@link PacketRouter}, keeping for itself only the two that concern the link: a CONFIGpac (the
 * robot's configuration, read while connecting) and a controller reset (the link is lost).
 *
 * <p>Connecting runs on whichever thread drives the robot: the caller of {@code blockingConnect},
 * or the cycle thread for {@code asyncConnect}. The link drives the {@link Handshake} and acts on
 * what each step reports; once OPEN is sent it reads and hands on the robot's packets itself, as in
 * a cycle, and tells the handshake what it heard. What the rest of the robot must do when the link
 * changes it learns through {@link Events}, as values; the link knows nothing else of the robot.
 */
final class RobotLink {

  private static final Logger log = LoggerFactory.getLogger(RobotLink.class);

  /** What the rest of the robot does when the link changes. */
  interface Events {
    /** A connection attempt starts: forget the state of an earlier connection. */
    void connecting();

    /** The handshake named the robot and its parameters were loaded. */
    void identified(ArRobotParams params);

    /** The handshake has the CONFIGpac (or gave up waiting): the speed limits to start with. */
    void configured(ConfiguredLimits limits);
  }

  private final Clock clock;
  private final ArRobotPacketSender sender;
  private final PacketIntake intake;
  private final PacketRouter router;
  private final ReentrantLock robotLock;
  private final LongSupplier cycleTimeMs;
  private final BooleanSupplier cycleRunning;
  private final Events events;
  final Callbacks connectCBs = new Callbacks("connect");
  final Callbacks failedConnectCBs = new Callbacks("failed connect");
  final Callbacks disconnectNormallyCBs = new Callbacks("disconnect normally");
  final Callbacks disconnectOnErrorCBs = new Callbacks("disconnect on error");
  private volatile ArDeviceConnection conn;
  private volatile boolean connected;
  private volatile Handshake handshake;
  private volatile CountDownLatch connectDone = new CountDownLatch(0);
  private volatile String failure = "";
  private volatile String robotName = "";
  private volatile String robotType = "";
  private volatile String robotSubType = "";
  private volatile ArRobotParams params = ArRobotParams.defaults();
  private volatile ArConfigPacket config;
  private volatile Path paramsDir = defaultParamsDirectory();
  private volatile long timeoutMs = 8000;

  /**
   * A link that writes through {@code sender}, counts dropped packets in {@code drops}, and hands
   * packets to {@code router} holding {@code robotLock}.
   *
   * @param cycleTimeMs the robot's cycle time (the handshake waits one cycle before OPEN)
   * @param cycleRunning whether the robot's cycle runs on a thread of its own (which then carries
   *     the handshake)
   */
  RobotLink(
      Clock clock,
      ArRobotPacketSender sender,
      DropCounters drops,
      PacketRouter router,
      ReentrantLock robotLock,
      LongSupplier cycleTimeMs,
      BooleanSupplier cycleRunning,
      Events events) {
    this.clock = clock;
    this.sender = sender;
    this.intake = new PacketIntake(drops);
    this.router = router;
    this.robotLock = robotLock;
    this.cycleTimeMs = cycleTimeMs;
    this.cycleRunning = cycleRunning;
    this.events = events;
  }

  void setDeviceConnection(ArDeviceConnection c) {
    conn = c;
    sender.setDeviceConnection(c);
  }

  ArDeviceConnection getDeviceConnection() {
    return conn;
  }

  boolean isConnected() {
    return connected;
  }

  boolean isConnecting() {
    return handshake != null;
  }

  String failure() {
    return failure;
  }

  String robotName() {
    return robotName;
  }

  String robotType() {
    return robotType;
  }

  String robotSubType() {
    return robotSubType;
  }

  ArConfigPacket config() {
    return config;
  }

  /**
   * Where a robot's own parameter files are looked for unless the program says otherwise: the
   * folder named by the {@code JARIA_PARAMS} environment variable, else {@code ~/.jaria/params}
   * (ARIA's {@code /usr/local/Aria/params} in a user's home).
   */
  static Path defaultParamsDirectory() {
    String env = System.getenv("JARIA_PARAMS");
    if (env != null && !env.isBlank()) {
      return Path.of(env);
    }
    return Path.of(System.getProperty("user.home", "."), ".jaria", "params");
  }

  Path paramsDirectory() {
    return paramsDir;
  }

  void setParamsDirectory(Path dir) {
    paramsDir = dir;
  }

  void setTimeoutMs(long ms) {
    timeoutMs = ms;
  }

  long timeoutMs() {
    return timeoutMs;
  }

  // ---------------------------------------------------------------- connecting

  /**
   * Records that no connection could even be opened (the connector's case). Like a failed handshake
   * it is not logged: the program asks {@code getConnectFailure()} and says it once.
   */
  void openFailed(String reason) {
    failure = reason;
    log.debug("cannot connect: {}", reason);
    failedConnectCBs.invokeAll();
  }

  /** Replaces the failure's explanation with a fuller one (the connector adds what it tried). */
  void explainFailure(String why) {
    failure = why;
  }

  boolean asyncConnect() {
    if (conn == null) {
      failure = "no device connection set: call setDeviceConnection first";
      log.warn("cannot connect: {}", failure);
      failedConnectCBs.invokeAll();
      return false;
    }
    if (connected || handshake != null) {
      return true;
    }
    failure = "";
    config = null;
    events.connecting();
    connectDone = new CountDownLatch(1);
    handshake = new Handshake(sender, intake, Math.max(1, cycleTimeMs.getAsLong()));
    return true;
  }

  boolean blockingConnect() {
    if (!asyncConnect()) {
      return false;
    }
    if (cycleRunning.getAsBoolean()) {
      // The cycle thread carries the handshake; wait for it to finish.
      try {
        connectDone.await(30, TimeUnit.SECONDS);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
      return connected;
    }
    while (handshake != null) {
      stepConnecting(clock.nanoTime());
      waitWhileConnecting(Long.MAX_VALUE);
    }
    return connected;
  }

  /**
   * While a handshake is in progress, waits for bytes until its next deadline or {@code limit},
   * whichever is earlier.
   */
  void waitWhileConnecting(long limit) {
    Handshake h = handshake;
    if (h != null) {
      waitForBytes(Math.min(limit, h.nextDeadline()));
    }
  }

  private void waitForBytes(long deadline) {
    ArDeviceConnection c = conn;
    if (c == null || c.getStatus() != ArDeviceConnection.Status.OPEN) {
      return;
    }
    try {
      intake.waitForPacket(c, clock, deadline);
    } catch (IOException e) {
      // The next step notices the broken connection and fails the handshake.
      log.debug("read failed while connecting: {}", e.getMessage());
    }
  }

  /**
   * Advances a handshake in progress by one step.
   *
   * @return true if a handshake is (or was, until this step) in progress
   */
  boolean stepConnecting(long now) {
    Handshake h = handshake;
    if (h == null) {
      return false;
    }
    Handshake.Result r =
        h.step(conn, now, h.isOpen() ? handOnWhileOpening(h, now) : Handshake.NOTHING);
    if (r == Handshake.Result.IDENTIFIED) {
      identified(h.identity());
    } else if (r == Handshake.Result.CONFIGURED) {
      configured();
      r = h.step(conn, now, new Handshake.Heard(config, false, params.getSwitchToBaudRate()));
    }
    switch (r) {
      case CONNECTED -> {
        handshake = null;
        connected = true;
        intake.touch(now);
        log.info("connected to {} ({})", robotName, conn.getPortName());
        connectDone.countDown();
        connectCBs.invokeAll();
      }
      case FAILED -> {
        handshake = null;
        failure = h.failure();
        connectDone.countDown();
        failedConnectCBs.invokeAll();
      }
      case IN_PROGRESS, IDENTIFIED, CONFIGURED -> {
        // keep going
      }
    }
    return true;
  }

  /**
   * After OPEN the robot's packets go their normal way before the handshake looks: read what has
   * arrived, and hand it on holding the robot's lock (SIPs to the handlers, a CONFIGpac kept here).
   */
  private Handshake.Heard handOnWhileOpening(Handshake h, long now) {
    try {
      intake.readAvailable(conn, now);
    } catch (IOException e) {
      h.connectionLost(e.getMessage());
    }
    boolean arrived = intake.hasPacket();
    robotLock.lock();
    try {
      handOnQueued();
    } finally {
      robotLock.unlock();
    }
    return new Handshake.Heard(config, arrived, params.getSwitchToBaudRate());
  }

  /** The SYNC2 echo named the robot: load its parameters and tell the robot. */
  private void identified(Handshake.Identity id) {
    robotName = id.name();
    robotType = id.type();
    robotSubType = id.subtype();
    ArRobotParams p = ArRobotParams.load(id.subtype(), id.name(), paramsDir);
    // which files the robot runs on; problems were logged as ERRORs by the loader
    log.info("robot parameters for '{}' from {}", id.subtype(), p.getSources());
    params = p;
    events.identified(p);
  }

  /**
   * The CONFIGpac came (or never will): the robot takes its speed limits as a value, and the link
   * asks for the packet streams the parameters want.
   */
  private void configured() {
    ArRobotParams p = params;
    events.configured(ConfiguredLimits.of(config, p));
    if (p.getRequestIOPackets()) {
      sender.comInt(ArCommands.IOREQUEST.getNumber(), 2);
    }
    if (p.getRequestEncoderPackets()) {
      sender.comInt(ArCommands.ENCODER.getNumber(), 2);
    }
  }

  // ---------------------------------------------------------------- packets

  /** Reads what has arrived into the queue; a failed read means the connection is lost. */
  void readAvailable(long now) {
    ArDeviceConnection c = conn;
    if (c == null) {
      return;
    }
    try {
      intake.readAvailable(c, now);
    } catch (IOException e) {
      lostConnection(e.getMessage());
    }
  }

  /** Reads until a SIP arrives or the deadline passes (for the cycle chained to SIPs). */
  void waitForSip(long deadline) {
    ArDeviceConnection c = conn;
    if (c == null || !connected) {
      return;
    }
    try {
      intake.waitForSip(c, clock, deadline);
    } catch (IOException e) {
      lostConnection(e.getMessage());
    }
  }

  /** Whether a standard SIP is waiting in the queue. */
  boolean hasSip() {
    return intake.hasSip();
  }

  /** Hands every queued packet on, oldest first. Call holding the robot's lock. */
  void handOnQueued() {
    ArRobotPacket p;
    while ((p = intake.poll()) != null) {
      handOn(p);
    }
  }

  /** Keeps the packets that concern the link, and routes the others. */
  private void handOn(ArRobotPacket p) {
    int id = p.getID();
    if (id == PacketIds.CONTROLLER_RESET || id == PacketIds.CONTROLLER_RESET_2) {
      lostConnection("the robot's controller was reset");
    } else if (id == PacketIds.CONFIG) {
      ArConfigPacket c = ArConfigPacket.decode(p);
      if (c == null) {
        intake.drops().drop(DropReason.MALFORMED, "short CONFIGpac");
      } else {
        config = c;
      }
    } else {
      router.route(p);
    }
  }

  void checkTimeout(long now) {
    if (connected
        && timeoutMs > 0
        && now - intake.lastPacketNanos() > TimeUnit.MILLISECONDS.toNanos(timeoutMs)) {
      lostConnection("nothing received from the robot in " + timeoutMs + " ms");
    }
  }

  /** The link broke: drop the connection and tell the disconnect-on-error callbacks. */
  void lostConnection(String why) {
    if (!connected) {
      return;
    }
    connected = false;
    log.warn("lost connection to the robot: {}", why);
    ArDeviceConnection c = conn;
    if (c != null) {
      c.close();
    }
    disconnectOnErrorCBs.invokeAll();
  }

  boolean disconnect() {
    Handshake h = handshake;
    if (h != null) {
      handshake = null;
      failure = "connection attempt cancelled by disconnect()";
      connectDone.countDown();
    }
    if (!connected) {
      return false;
    }
    sender.comInt(ArCommands.CLOSE.getNumber(), 1);
    connected = false;
    ArDeviceConnection c = conn;
    if (c != null) {
      c.close();
    }
    log.info("disconnected from {}", robotName);
    disconnectNormallyCBs.invokeAll();
    return true;
  }
}
