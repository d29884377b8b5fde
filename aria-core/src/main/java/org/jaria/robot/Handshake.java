package org.jaria.robot;

import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The ARCOS connection handshake as a state machine that never blocks: SYNC0, SYNC1, SYNC2 with
 * their echoes (restarting on a wrong reply, closing an old session that still streams SIPs),
 * reading name/type/subtype from the SYNC2 echo, OPEN, the CONFIG request and CONFIGpac, and on
 * serial ports the switch to a faster baud rate. Each {@link #step} looks at what has arrived and
 * at the clock, sends what is due, and returns; so the same code serves {@code blockingConnect}
 * (which waits for bytes between steps) and {@code asyncConnect} on a virtual clock (where a
 * simulator advances time between steps).
 *
 * <p>The retry rules follow ARIA: one second per reply, a sequence restarted on a wrong ID, an OPEN
 * to dislodge a robot that is connected but not open after three silent tries, and failure after
 * more than ten silent tries (or five if the robot never answered at all).
 */
final class Handshake {

  private static final Logger log = LoggerFactory.getLogger(Handshake.class);
  private static final long REPLY_NANOS = TimeUnit.MILLISECONDS.toNanos(1000);
  private static final long CLOSE_OLD_NANOS = TimeUnit.MILLISECONDS.toNanos(500);
  private static final long CONFIG_NANOS = TimeUnit.MILLISECONDS.toNanos(1000);
  private static final long BAUD_NANOS = TimeUnit.MILLISECONDS.toNanos(900);

  /** What the handshake needs from the robot it connects. */
  interface Host {
    /** Called once the SYNC2 echo names the robot; loads its parameters. */
    void identified(String name, String type, String subtype);

    /** Hands a packet received after OPEN to the robot's normal packet handling. */
    void dispatch(ArRobotPacket p);

    /** Whether a CONFIGpac has arrived since OPEN. */
    boolean hasConfig();

    /** Sets speed limits from the CONFIGpac (or the parameters when none came). */
    void applyLimits(boolean gotConfig);

    /** Baud rate to switch a serial connection to, 0 for none. */
    int switchToBaudRate();

    /** Whether the robot's CONFIGpac says it can change baud rate. */
    boolean robotCanResetBaud();
  }

  /** The outcome of a step. */
  enum Result {
    IN_PROGRESS,
    CONNECTED,
    FAILED
  }

  private enum State {
    START,
    SYNC,
    CLOSING_OLD,
    PRE_OPEN,
    WAIT_CONFIG,
    BAUD_SENT,
    DONE,
    FAILED
  }

  private final ArRobotPacketSender sender;
  private final PacketIntake intake;
  private final Host host;
  private final long cycleNanos;
  private State state = State.START;
  private int syncIndex;
  private long sentAt;
  private long deadline;
  private int timesTried;
  private int noPacketCount;
  private int startBaud;
  private String failure = "";

  Handshake(ArRobotPacketSender sender, PacketIntake intake, Host host, long cycleMillis) {
    this.sender = sender;
    this.intake = intake;
    this.host = host;
    this.cycleNanos = TimeUnit.MILLISECONDS.toNanos(cycleMillis);
  }

  /** Why the handshake failed (empty while it has not). */
  String failure() {
    return failure;
  }

  /** The clock time by which something must happen next (for a caller that waits for bytes). */
  long nextDeadline() {
    return deadline;
  }

  /**
   * Advances the handshake: reads what has arrived (without waiting), sends what is due.
   *
   * @param conn the robot's connection (opened here if needed)
   * @param now the clock's current time
   */
  Result step(ArDeviceConnection conn, long now) {
    try {
      if (state == State.START) {
        start(conn, now);
      }
      if (state != State.FAILED && state != State.DONE) {
        intake.readAvailable(conn, now);
      }
      switch (state) {
        case SYNC -> syncStep(now);
        case CLOSING_OLD -> closingStep(now);
        case PRE_OPEN -> preOpenStep(now);
        case WAIT_CONFIG -> configStep(conn, now);
        case BAUD_SENT -> baudStep(conn, now);
        case START, DONE, FAILED -> {
          // nothing to do
        }
      }
    } catch (IOException e) {
      fail("lost the connection while connecting: " + e.getMessage());
    }
    return switch (state) {
      case DONE -> Result.CONNECTED;
      case FAILED -> Result.FAILED;
      default -> Result.IN_PROGRESS;
    };
  }

  private void start(ArDeviceConnection conn, long now) throws IOException {
    if (conn.getStatus() != ArDeviceConnection.Status.OPEN) {
      try {
        conn.open();
      } catch (IOException e) {
        fail("could not open " + conn.getPortName() + ": " + e.getMessage());
        return;
      }
    }
    // Whatever was waiting is from before this connection: forget it.
    intake.readAvailable(conn, now);
    intake.clear();
    state = State.SYNC;
    sendSync(0, now);
  }

  private void sendSync(int index, long now) {
    syncIndex = index;
    timesTried++;
    sender.com(index);
    sentAt = now;
    deadline = now + REPLY_NANOS;
    log.debug("syncing {}", index);
  }

  private void syncStep(long now) {
    ArRobotPacket p;
    while (state == State.SYNC && (p = intake.poll()) != null) {
      int id = p.getID();
      if (PacketIds.isStandardSip(id)) {
        log.info("robot is still open from an earlier connection: closing it first");
        sender.comInt(ArCommands.CLOSE.getNumber(), 1);
        state = State.CLOSING_OLD;
        deadline = now + CLOSE_OLD_NANOS;
        return;
      }
      if (id != syncIndex) {
        sendSync(0, now);
        continue;
      }
      if (syncIndex < 2) {
        sendSync(syncIndex + 1, now);
        continue;
      }
      String name = p.bufToString();
      String type = p.bufToString();
      String subtype = p.bufToString().toLowerCase(Locale.ROOT);
      log.info("connected to robot '{}', type '{}', subtype '{}'", name, type, subtype);
      host.identified(name, type, subtype);
      state = State.PRE_OPEN;
      deadline = now + cycleNanos;
      return;
    }
    if (state == State.SYNC && now - sentAt >= REPLY_NANOS) {
      noPacketCount++;
      if ((noPacketCount > 5 && noPacketCount >= timesTried) || noPacketCount > 10) {
        fail("no robot is responding: check the cable, that the robot is on, and the port");
        return;
      }
      if (noPacketCount > 3) {
        // A robot that is connected but not open answers OPEN with SIPs.
        sender.comInt(ArCommands.OPEN.getNumber(), 1);
      }
      sendSync(0, now);
    }
    if (timesTried > 50) {
      fail("the robot never completed the handshake after " + timesTried + " tries");
    }
  }

  private void closingStep(long now) {
    ArRobotPacket p;
    while ((p = intake.poll()) != null) {
      if (PacketIds.isStandardSip(p.getID())) {
        sender.comInt(ArCommands.CLOSE.getNumber(), 1);
      }
    }
    if (now >= deadline) {
      state = State.SYNC;
      sendSync(0, now);
    }
  }

  private void preOpenStep(long now) {
    if (now < deadline) {
      return;
    }
    sender.comInt(ArCommands.OPEN.getNumber(), 1);
    sender.comInt(ArCommands.CONFIG.getNumber(), 1);
    state = State.WAIT_CONFIG;
    sentAt = now;
    deadline = now + CONFIG_NANOS;
  }

  private void configStep(ArDeviceConnection conn, long now) {
    dispatchAll();
    boolean got = host.hasConfig();
    if (!got && now - sentAt < CONFIG_NANOS) {
      return;
    }
    host.applyLimits(got);
    int baud = host.switchToBaudRate();
    if (got && baud > 0 && host.robotCanResetBaud() && conn instanceof ArSerialConnection serial) {
      int code = baudCode(baud);
      if (code >= 0 && serial.getBaud() != baud) {
        startBaud = serial.getBaud();
        sender.comInt(ArCommands.HOSTBAUD.getNumber(), code);
        serial.setBaud(baud);
        sender.com(ArCommands.PULSE.getNumber());
        state = State.BAUD_SENT;
        sentAt = now;
        deadline = now + BAUD_NANOS;
        return;
      }
      if (code < 0) {
        log.warn(
            "SwitchToBaudRate {} is not a Pioneer baud rate; staying at {}",
            baud,
            serial.getBaud());
      }
    }
    state = State.DONE;
  }

  private void baudStep(ArDeviceConnection conn, long now) {
    boolean any = intake.hasPacket();
    dispatchAll();
    if (any) {
      state = State.DONE;
    } else if (now - sentAt > BAUD_NANOS) {
      log.info("robot did not switch baud rate; going back to {}", startBaud);
      ((ArSerialConnection) conn).setBaud(startBaud);
      state = State.DONE;
    }
  }

  private void dispatchAll() {
    ArRobotPacket p;
    while ((p = intake.poll()) != null) {
      host.dispatch(p);
    }
  }

  private void fail(String message) {
    failure = message;
    state = State.FAILED;
    log.warn("could not connect: {}", message);
  }

  /** ARCOS's code for a baud rate (HOSTBAUD argument), or −1. */
  static int baudCode(int baud) {
    return switch (baud) {
      case 9600 -> 0;
      case 19200 -> 1;
      case 38400 -> 2;
      case 57600 -> 3;
      case 115200 -> 4;
      default -> -1;
    };
  }
}
