package org.jaria.robot;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot's connection life: connecting (through {@link Handshake}), noticing a lost link, and
 * disconnecting, with the matching callbacks. Connecting runs on whichever thread drives the robot:
 * the caller of {@code blockingConnect}, or the cycle thread for {@code asyncConnect}.
 */
final class RobotConnection implements Handshake.Host {

  private static final Logger log = LoggerFactory.getLogger(RobotConnection.class);

  private final ArRobot robot;
  private volatile ArDeviceConnection conn;
  private volatile boolean connected;
  private volatile Handshake handshake;
  private volatile CountDownLatch connectDone = new CountDownLatch(0);
  private volatile String failure = "";
  private volatile String robotName = "";
  private volatile String robotType = "";
  private volatile String robotSubType = "";
  private volatile ArConfigPacket config;
  private volatile Path paramsDir = defaultParamsDirectory();
  private volatile long timeoutMs = 8000;

  RobotConnection(ArRobot robot) {
    this.robot = robot;
  }

  void setDeviceConnection(ArDeviceConnection c) {
    conn = c;
    robot.sender.setDeviceConnection(c);
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

  /** Records that no connection could even be opened (the connector's case) and says so. */
  void openFailed(String reason) {
    failure = reason;
    log.warn("cannot connect: {}", reason);
    robot.failedConnectCBs.invokeAll();
  }

  boolean asyncConnect() {
    if (conn == null) {
      failure = "no device connection set: call setDeviceConnection first";
      log.warn("cannot connect: {}", failure);
      robot.failedConnectCBs.invokeAll();
      return false;
    }
    if (connected || handshake != null) {
      return true;
    }
    failure = "";
    config = null;
    robot.resetState();
    robot.motion.reset();
    connectDone = new CountDownLatch(1);
    handshake = new Handshake(robot.sender, robot.intake, this, Math.max(1, robot.getCycleTime()));
    return true;
  }

  boolean blockingConnect() {
    if (!asyncConnect()) {
      return false;
    }
    if (robot.isRunning()) {
      // The cycle thread carries the handshake; wait for it to finish.
      try {
        connectDone.await(30, TimeUnit.SECONDS);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
      return connected;
    }
    while (handshake != null) {
      stepConnecting(robot.getClock().nanoTime());
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
      robot.intake.waitForPacket(c, robot.getClock(), deadline);
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
    switch (h.step(conn, now)) {
      case CONNECTED -> {
        handshake = null;
        connected = true;
        robot.intake.touch(now);
        log.info("connected to {} ({})", robotName, conn.getPortName());
        connectDone.countDown();
        robot.connectCBs.invokeAll();
      }
      case FAILED -> {
        handshake = null;
        failure = h.failure();
        connectDone.countDown();
        robot.failedConnectCBs.invokeAll();
      }
      case IN_PROGRESS -> {
        // keep going
      }
    }
    return true;
  }

  @Override
  public void identified(String name, String type, String subtype) {
    robotName = name;
    robotType = type;
    robotSubType = subtype;
    ArRobotParams p = ArRobotParams.load(subtype, name, paramsDir);
    // which files the robot runs on; problems were logged as ERRORs by the loader
    log.info("robot parameters for '{}' from {}", subtype, p.getSources());
    robot.setParams(p);
    robot.motion.configure(
        p.hasSettableVelMaxes(), p.hasSettableAccsDecs(), p.hasMoveCommand(), p.getVel2Divisor());
  }

  @Override
  public void dispatch(ArRobotPacket p) {
    robot.robotLock.lock();
    try {
      robot.dispatch(p);
    } finally {
      robot.robotLock.unlock();
    }
  }

  @Override
  public boolean hasConfig() {
    return config != null;
  }

  /** Speed limits as ARIA sets them: CONFIGpac values, overridden by non-zero parameters. */
  @Override
  public void applyLimits(boolean gotConfig) {
    ArRobotParams p = robot.params;
    ArConfigPacket c = config;
    if (gotConfig && c != null) {
      robot.setAbsoluteMaxTransVel(c.getTransVelTop());
      robot.setAbsoluteMaxRotVel(c.getRotVelTop());
      robot.setTransVelMax(c.getTransVelMax());
      robot.setRotVelMax(c.getRotVelMax());
      robot.setTransAccel(c.getInt(ArConfigPacket.Field.TRANS_ACCEL));
      robot.setTransDecel(c.getInt(ArConfigPacket.Field.TRANS_DECEL));
      robot.setRotAccel(c.getInt(ArConfigPacket.Field.ROT_ACCEL));
      robot.setRotDecel(c.getInt(ArConfigPacket.Field.ROT_DECEL));
    } else {
      robot.setAbsoluteMaxTransVel(p.getAbsoluteMaxVelocity());
      robot.setAbsoluteMaxRotVel(p.getAbsoluteMaxRotVelocity());
    }
    if (Math.abs(p.getTransVelMax()) > 1) {
      robot.setTransVelMax(p.getTransVelMax());
    } else if (!gotConfig) {
      robot.setTransVelMax(p.getAbsoluteMaxVelocity());
    }
    if (Math.abs(p.getRotVelMax()) > 1) {
      robot.setRotVelMax(p.getRotVelMax());
    } else if (!gotConfig) {
      robot.setRotVelMax(p.getAbsoluteMaxRotVelocity());
    }
    if (Math.abs(p.getTransAccel()) > 1) {
      robot.setTransAccel(p.getTransAccel());
    }
    if (Math.abs(p.getTransDecel()) > 1) {
      robot.setTransDecel(p.getTransDecel());
    }
    if (Math.abs(p.getRotAccel()) > 1) {
      robot.setRotAccel(p.getRotAccel());
    }
    if (Math.abs(p.getRotDecel()) > 1) {
      robot.setRotDecel(p.getRotDecel());
    }
    if (p.getRequestIOPackets()) {
      robot.requestIOPackets();
    }
    if (p.getRequestEncoderPackets()) {
      robot.requestEncoderPackets();
    }
  }

  @Override
  public int switchToBaudRate() {
    return robot.params.getSwitchToBaudRate();
  }

  @Override
  public boolean robotCanResetBaud() {
    ArConfigPacket c = config;
    return c != null && c.getInt(ArConfigPacket.Field.RESET_BAUD) != 0;
  }

  // ---------------------------------------------------------------- packets

  boolean handleConfig(ArRobotPacket p) {
    if (p.getID() != PacketIds.CONFIG) {
      return false;
    }
    ArConfigPacket c = ArConfigPacket.decode(p);
    if (c == null) {
      robot.drops.drop(DropReason.MALFORMED, "short CONFIGpac");
    } else {
      config = c;
    }
    return true;
  }

  boolean handleControllerReset(ArRobotPacket p) {
    if (p.getID() != PacketIds.CONTROLLER_RESET && p.getID() != PacketIds.CONTROLLER_RESET_2) {
      return false;
    }
    lostConnection("the robot's controller was reset");
    return true;
  }

  /** Reads what has arrived into the intake; a failed read means the connection is lost. */
  void readAvailable(long now) {
    ArDeviceConnection c = conn;
    if (c == null) {
      return;
    }
    try {
      robot.intake.readAvailable(c, now);
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
      robot.intake.waitForSip(c, robot.getClock(), deadline);
    } catch (IOException e) {
      lostConnection(e.getMessage());
    }
  }

  void checkTimeout(long now) {
    if (connected
        && timeoutMs > 0
        && now - robot.intake.lastPacketNanos() > TimeUnit.MILLISECONDS.toNanos(timeoutMs)) {
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
    robot.disconnectOnErrorCBs.invokeAll();
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
    robot.sender.comInt(ArCommands.CLOSE.getNumber(), 1);
    connected = false;
    ArDeviceConnection c = conn;
    if (c != null) {
      c.close();
    }
    log.info("disconnected from {}", robotName);
    robot.disconnectNormallyCBs.invokeAll();
    return true;
  }
}
