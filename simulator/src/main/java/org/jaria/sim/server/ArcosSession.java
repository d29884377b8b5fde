package org.jaria.sim.server;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.sim.robot.LaserModel;
import org.jaria.sim.robot.RobotBody;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One client connection to one simulated robot, seen from the robot: the ARCOS state machine.
 *
 * <p>Waiting for a client, the robot echoes SYNC0 and SYNC1 and answers SYNC2 with its name, type
 * and subtype (an out-of-order SYNC0 restarts the sequence; other packets are ignored). The answer
 * to SYNC2 is where a connection takes the robot: it is held back while the {@link Gate} says the
 * robot is taken, so a connection that has not completed the handshake never holds the robot (see
 * {@link RobotClients}). OPEN then starts the servers: a SIP every SIP cycle, sonar on, motors
 * disabled until ENABLE. In an open session IDs 0, 1 and 2 mean PULSE, OPEN and CLOSE, so a client
 * that restarts the handshake on a robot still open from an earlier client gets a SIP in answer to
 * its SYNC0, sends CLOSE and starts again, exactly as with ARCOS. CLOSE stops the robot and returns
 * to waiting; the connection stays up. The watchdog stops the robot when commands stop for the
 * watchdog time and lets it resume on the next command other than PULSE (see {@link
 * #packetReceived}).
 *
 * <p>The world thread drives it: {@link #poll} reads whatever arrived (never blocking) and executes
 * it, {@link #afterPhysics} sends what is due.
 */
public final class ArcosSession implements ArRobotPacketReceiver.Listener {

  private static final Logger log = LoggerFactory.getLogger(ArcosSession.class);

  /** Decides whether a session that has just completed the handshake may take the robot. */
  @FunctionalInterface
  public interface Gate {
    /**
     * Whether {@code s}, which has just sent SYNC2, may hold the robot now; if so, it holds it from
     * this call on (and whoever held it before has been let go).
     */
    boolean mayHold(ArcosSession s);

    /** A gate that always lets the session in (a robot with only ever one connection). */
    Gate ALWAYS = s -> true;
  }

  /** Where the session is in its life. */
  public enum State {
    /** Waiting for the SYNC0/SYNC1/SYNC2 handshake. */
    SYNC,
    /** Handshake done, waiting for OPEN. */
    CONNECTED,
    /** Servers running. */
    OPEN,
    /** The connection is gone. */
    ENDED
  }

  final RobotBody body;
  final SessionHost host;
  private final ArDeviceConnection conn;
  private final ArRobotPacketReceiver receiver;
  private final CommandHandler commands;
  private final byte[] readBuf = new byte[2048];
  private final ArRobotPacket out = new ArRobotPacket();
  private final StandardSip sip = new StandardSip();

  private final ClientKind kind;
  private final Gate gate;
  private final long connectedNanos;
  private State state = State.SYNC;
  private int expectedSync;
  private long handshakeSinceNanos;
  private long lastPacketNanos;
  private boolean sentPacket;
  private boolean awaitingRobot;
  private boolean timedOut;
  private long lastCommandNanos;
  private boolean watchdogTripped;
  private long nextSipNanos;
  private long sipsSent;

  // Packet requests of the session (0 none, 1 one, 2 continuous).
  int encoderMode;
  int ioMode;
  int gripMode;
  int joyMode;
  int simStatMode;
  int laserMode;
  boolean tcm2Once;
  int gyroCw;
  int gyroCcw;

  /**
   * A session on a freshly connected in-memory client (never timed out, trusted as local).
   *
   * @param drops the robot's drop counters (kept across sessions)
   */
  public ArcosSession(
      RobotBody body, ArDeviceConnection conn, SessionHost host, DropCounters drops) {
    this(body, conn, host, drops, ClientKind.IN_MEMORY, Gate.ALWAYS);
  }

  /**
   * A session on a freshly connected client of kind {@code kind}: network clients must complete the
   * handshake within the host's handshake timeout and are disconnected when silent for the client
   * timeout.
   *
   * @param drops the robot's drop counters (kept across sessions)
   * @param gate asked, when the client has sent SYNC2, whether it may take the robot
   */
  public ArcosSession(
      RobotBody body,
      ArDeviceConnection conn,
      SessionHost host,
      DropCounters drops,
      ClientKind kind,
      Gate gate) {
    this.body = body;
    this.conn = conn;
    this.host = host;
    this.kind = kind;
    this.gate = gate;
    this.receiver = new ArRobotPacketReceiver(drops);
    this.commands = new CommandHandler(this);
    this.connectedNanos = host.clock().nanoTime();
    this.handshakeSinceNanos = connectedNanos;
    this.lastPacketNanos = connectedNanos;
  }

  /** Where the client is. */
  public ClientKind kind() {
    return kind;
  }

  /** Whether the session ended because the client was too slow or silent. */
  public boolean timedOut() {
    return timedOut;
  }

  /** The session's state. */
  public State state() {
    return state;
  }

  /** Whether the session holds the robot: it completed the handshake and has not closed. */
  public boolean holdsRobot() {
    return state == State.CONNECTED || state == State.OPEN;
  }

  /** Whether the client sent SYNC2 and waits for the answer because the robot is taken. */
  public boolean awaitingRobot() {
    return awaitingRobot;
  }

  /** When the connection was made (the session's clock). */
  public long connectedNanos() {
    return connectedNanos;
  }

  /**
   * When the client last sent a whole, valid packet (its connection time before the first): bytes
   * that do not make a packet are not activity.
   */
  public long lastPacketNanos() {
    return lastPacketNanos;
  }

  /** Whether the client has sent one whole, valid packet yet. */
  public boolean sentPacket() {
    return sentPacket;
  }

  /**
   * Asks the gate again for a client that waits for the robot (its SYNC2 held back), and answers
   * SYNC2 if the robot is now free for it.
   */
  public void retryHold() {
    if (awaitingRobot && state == State.SYNC && gate.mayHold(this)) {
      completeHandshake();
    }
  }

  /** The client connection. */
  public ArDeviceConnection connection() {
    return conn;
  }

  /** SIPs sent in this session. */
  public long sipsSent() {
    return sipsSent;
  }

  /** Whether the watchdog is holding the robot. */
  public boolean watchdogTripped() {
    return watchdogTripped;
  }

  /** Reads and executes everything the client sent; ends the session if the client is gone. */
  public void poll(long now) {
    if (state == State.ENDED) {
      return;
    }
    try {
      while (true) {
        int n = conn.read(readBuf, 0, readBuf.length, 0);
        if (n < 0) {
          end("the client closed the connection");
          return;
        }
        if (n == 0) {
          break;
        }
        receiver.feed(readBuf, 0, n, now, this);
        if (state == State.ENDED) {
          return;
        }
      }
      receiver.checkTimeout(now, this);
    } catch (IOException e) {
      end("the connection failed: " + e.getMessage());
    }
  }

  @Override
  public void packetReceived(ArRobotPacket p) {
    int id = p.getID();
    lastPacketNanos = host.clock().nanoTime();
    sentPacket = true;
    switch (state) {
      case SYNC -> handleSync(id);
      case CONNECTED -> {
        if (id == 1) {
          open();
        } else if (id == 2) {
          toSync("CLOSE before OPEN");
        }
      }
      case OPEN -> {
        lastCommandNanos = host.clock().nanoTime();
        // PULSE (and OPEN) keep the session alive but do not release a robot the watchdog
        // stopped: a reconnecting client's SYNC0 is byte for byte a PULSE, and the robot must
        // answer it with a "stopped" SIP instead of driving off on the old client's setpoint.
        if (watchdogTripped && id > 1) {
          watchdogTripped = false;
          body.motion().setHeld(false);
          log.info("{}: commands arrive again; watchdog released", body.name());
        } else if (watchdogTripped && host.watchdogWarnOnly()) {
          watchdogTripped = false;
        }
        IgnoredCommand.Reason refused = host.commandPolicy().refusal(id, simCtrlOp(p), kind);
        if (refused != null) {
          host.ignoredCommand(id, refused, body.name());
          if (CommandPolicy.isMapLoad(simCtrlOp(p))) {
            // a refused map load still gets its answer, so the client does not wait for ever
            send(ServerPackets.mapChanged(out, false, -1, ""));
          }
          return;
        }
        commands.handle(p);
      }
      case ENDED -> {}
    }
  }

  /** The operation code of a SIM_CTRL packet (-1 for other packets or without one). */
  private static int simCtrlOp(ArRobotPacket p) {
    if (p.getID() != ArCommands.SIM_CTRL.getNumber() || p.getDataLength() < 3) {
      return -1;
    }
    p.resetRead();
    p.bufToUByte();
    int op = p.bufToByte2();
    p.resetRead();
    return op;
  }

  private void handleSync(int id) {
    if (id == expectedSync || id == 0) {
      if (id == 2) {
        awaitingRobot = true;
        if (gate.mayHold(this)) {
          completeHandshake();
        }
      } else {
        awaitingRobot = false;
        send(ServerPackets.syncEcho(out, id));
        expectedSync = id + 1;
      }
    }
  }

  /** SYNC2's answer: the session holds the robot from now on. */
  private void completeHandshake() {
    awaitingRobot = false;
    send(ServerPackets.sync2(out, body.model()));
    state = State.CONNECTED;
    expectedSync = 0;
    log.debug("{}: handshake done", body.name());
  }

  private void open() {
    body.openSession();
    state = State.OPEN;
    long now = host.clock().nanoTime();
    lastCommandNanos = now;
    nextSipNanos = now;
    encoderMode = ioMode = gripMode = joyMode = simStatMode = laserMode = 0;
    tcm2Once = false;
    watchdogTripped = false;
    log.info("{}: client opened the robot ({})", body.name(), conn.getPortName());
  }

  /** CLOSE in an open session: the robot stops and waits for a new handshake. */
  void close() {
    toSync("CLOSE");
  }

  private void toSync(String why) {
    body.closeSession();
    state = State.SYNC;
    expectedSync = 0;
    handshakeSinceNanos = host.clock().nanoTime();
    log.info("{}: session closed ({}); waiting for SYNC0", body.name(), why);
  }

  /** Ends the session for good: the robot stops and the connection is closed. */
  public void end(String why) {
    if (state == State.ENDED) {
      return;
    }
    boolean held = holdsRobot();
    if (held) {
      // a connection that does not hold the robot must not stop it under its real client
      body.closeSession();
    }
    state = State.ENDED;
    conn.close();
    if (held) {
      log.info("{}: client gone: {}", body.name(), why);
    } else {
      // squatters come and go by the hundred: counted (RobotClients), not logged one by one
      log.debug("{}: connection closed before it held the robot: {}", body.name(), why);
    }
  }

  /** Sends a finalized packet to the client (a failed write ends the session). */
  public void sendPacket(ArRobotPacket p) {
    send(p);
  }

  /** Writes a packet; a failed write ends the session. */
  void send(ArRobotPacket p) {
    if (state == State.ENDED) {
      return;
    }
    try {
      conn.write(p.getBuf(), 0, p.getLength());
    } catch (IOException e) {
      end("cannot write to the client: " + e.getMessage());
    }
  }

  /** The robot's drop counters. */
  DropCounters drops() {
    return receiver.drops();
  }

  /** The session's reusable output packet. */
  ArRobotPacket out() {
    return out;
  }

  /** Runs the watchdog and sends everything due after the physics of a tick. */
  public void afterPhysics(long now) {
    if (kind.isNetwork() && checkTimeouts(now)) {
      return;
    }
    if (state != State.OPEN) {
      flush();
      return;
    }
    int wd = host.watchdogMillis();
    if (wd > 0 && !watchdogTripped && now - lastCommandNanos > TimeUnit.MILLISECONDS.toNanos(wd)) {
      watchdogTripped = true;
      if (host.watchdogWarnOnly()) {
        log.warn("{}: no command for {} ms (watchdog); warning only", body.name(), wd);
      } else {
        body.motion().setHeld(true);
        log.warn("{}: no command for {} ms; watchdog stops the robot", body.name(), wd);
      }
    }
    if (now >= nextSipNanos) {
      long cycle = TimeUnit.MILLISECONDS.toNanos(host.sipCycleMillis());
      nextSipNanos += cycle;
      if (nextSipNanos <= now) {
        nextSipNanos = now + cycle;
      }
      sendCycle();
    }
    flush();
  }

  /**
   * Ends the session of a network client that has not finished the handshake in time or has been
   * silent too long (the watchdog stopped the robot long before); returns whether it did.
   */
  private boolean checkTimeouts(long now) {
    if (state == State.SYNC || state == State.CONNECTED) {
      long limit = TimeUnit.MILLISECONDS.toNanos(host.handshakeTimeoutMillis());
      if (now - handshakeSinceNanos > limit) {
        timedOut = true;
        end(
            awaitingRobot
                ? "the robot stayed taken for " + host.handshakeTimeoutMillis() + " ms"
                : "no handshake within " + host.handshakeTimeoutMillis() + " ms");
        return true;
      }
    } else if (state == State.OPEN && host.clientTimeoutMillis() > 0) {
      long limit = TimeUnit.MILLISECONDS.toNanos(host.clientTimeoutMillis());
      if (now - lastCommandNanos > limit) {
        timedOut = true;
        end("silent for " + host.clientTimeoutMillis() + " ms; robot freed for other clients");
        return true;
      }
    }
    return false;
  }

  private void sendCycle() {
    if (body.gyro() != null && body.gyro().isStreaming()) {
      send(ServerPackets.gyro(out, body.gyro()));
    }
    if (simStatMode == 2) {
      send(ServerPackets.simStat(out, body, host));
    }
    if (joyMode > 0) {
      send(ServerPackets.joystick(out));
      joyMode = joyMode == 1 ? 0 : joyMode;
    }
    send(ServerPackets.sip(out, sip, body));
    sipsSent++;
    if (ioMode > 0) {
      send(ServerPackets.io(out, body));
      ioMode = ioMode == 1 ? 0 : ioMode;
    }
    if (encoderMode > 0) {
      send(ServerPackets.encoder(out, body));
      encoderMode = encoderMode == 1 ? 0 : encoderMode;
    }
    if (gripMode > 0) {
      send(ServerPackets.gripper(out, body));
      gripMode = gripMode == 1 ? 0 : gripMode;
    }
    int tcm = body.io().getCompassMode();
    if (tcm == 3 || tcm2Once) {
      send(ServerPackets.tcm2(out, body.trueTh()));
      tcm2Once = false;
    }
    LaserModel l = body.laser();
    if (laserMode > 0 && l != null) {
      l.scan(body.trueX(), body.trueY(), Math.toRadians(body.trueTh()), host.world(), body.index());
      for (int first = 0; first < l.lastCount(); first += ServerPackets.LASER_READINGS_PER_PACKET) {
        send(ServerPackets.laser(out, l, body, first, laserMode == 2));
      }
    }
  }

  private void flush() {
    if (state != State.ENDED && conn instanceof NioSocketConnection nio) {
      try {
        nio.flush();
      } catch (IOException e) {
        end("cannot write to the client: " + e.getMessage());
      }
    }
  }
}
