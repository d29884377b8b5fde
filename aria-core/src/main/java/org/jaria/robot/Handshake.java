package org.jaria.robot;

import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
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
 * <p>The handshake never calls back into the link that drives it: each step says what happened in
 * its {@link Result}, and the link acts on it (loads the robot's parameters when it is {@link
 * Result#IDENTIFIED}, sets the speed limits when it is {@link Result#CONFIGURED}). Once OPEN is
 * sent the robot's packets are the link's: it reads them and hands them on as in any cycle (so the
 * first SIPs reach the handlers and a CONFIGpac is kept), and tells the next step what it heard
 * ({@link Heard}).
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

  /**
   * The robot's name, type and subtype (lower case), from the SYNC2 echo.
   *
   * @param name the robot's name
   * @param type its type, e.g. "Pioneer"
   * @param subtype its subtype, e.g. "p3dx-sh"
   */
  record Identity(String name, String type, String subtype) {}

  /**
   * What the link heard from the robot, for a step after OPEN.
   *
   * @param config the CONFIGpac, once one came, else null
   * @param packetArrived whether any packet arrived since the previous step
   * @param switchToBaudRate the baud rate the robot's parameters ask a serial link to switch to, 0
   *     for none
   */
  record Heard(ArConfigPacket config, boolean packetArrived, int switchToBaudRate) {}

  /** Nothing heard: for the steps before OPEN, which read the robot's replies themselves. */
  static final Heard NOTHING = new Heard(null, false, 0);

  /** The outcome of a step. */
  enum Result {
    /** Still connecting. */
    IN_PROGRESS,
    /** The SYNC2 echo named the robot ({@link #identity()}): load its parameters. */
    IDENTIFIED,
    /**
     * The CONFIGpac came, or waiting for it timed out: set the speed limits now, then step again at
     * once (a serial link may switch its baud rate next).
     */
    CONFIGURED,
    /** Connected: the robot is open. */
    CONNECTED,
    /** The attempt failed ({@link #failure()} says why). */
    FAILED
  }

  private enum State {
    START,
    SYNC,
    CLOSING_OLD,
    PRE_OPEN,
    WAIT_CONFIG,
    CONFIGURED,
    BAUD_SENT,
    DONE,
    FAILED
  }

  private final ArRobotPacketSender sender;
  private final PacketIntake intake;
  private final long cycleNanos;
  private State state = State.START;
  private Identity identity;
  private int syncIndex;
  private long sentAt;
  private long deadline;
  private int timesTried;
  private int noPacketCount;
  private int startBaud;
  private String failure = "";

  Handshake(ArRobotPacketSender sender, PacketIntake intake, long cycleMillis) {
    this.sender = sender;
    this.intake = intake;
    this.cycleNanos = TimeUnit.MILLISECONDS.toNanos(cycleMillis);
  }

  /** Why the handshake failed (empty while it has not). */
  String failure() {
    return failure;
  }

  /** The robot's name, type and subtype, once {@link Result#IDENTIFIED}; null before. */
  Identity identity() {
    return identity;
  }

  /** The clock time by which something must happen next (for a caller that waits for bytes). */
  long nextDeadline() {
    return deadline;
  }

  /**
   * Whether OPEN was sent and the handshake is not over: the robot's packets are then the link's to
   * read and hand on before each step.
   */
  boolean isOpen() {
    return state == State.WAIT_CONFIG || state == State.CONFIGURED || state == State.BAUD_SENT;
  }

  /** The link could not read from the robot after OPEN: the attempt fails. */
  void connectionLost(String why) {
    fail("lost the connection while connecting: " + why);
  }

  /**
   * Advances the handshake: before OPEN reads what has arrived (without waiting); sends what is
   * due.
   *
   * @param conn the robot's connection (opened here if needed)
   * @param now the clock's current time
   * @param heard what the link heard since the last step, once {@link #isOpen()}
   */
  Result step(ArDeviceConnection conn, long now, Heard heard) {
    boolean identifiedNow = false;
    try {
      if (state == State.START) {
        start(conn, now);
      }
      if (state == State.SYNC || state == State.CLOSING_OLD || state == State.PRE_OPEN) {
        intake.readAvailable(conn, now);
      }
      switch (state) {
        case SYNC -> identifiedNow = syncStep(now);
        case CLOSING_OLD -> closingStep(now);
        case PRE_OPEN -> preOpenStep(now);
        case WAIT_CONFIG -> configStep(now, heard);
        case CONFIGURED -> switchBaud(conn, now, heard);
        case BAUD_SENT -> baudStep(conn, now, heard);
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
      case CONFIGURED -> Result.CONFIGURED;
      default -> identifiedNow ? Result.IDENTIFIED : Result.IN_PROGRESS;
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

  /** One step of the SYNC sequence; true when the SYNC2 echo named the robot. */
  private boolean syncStep(long now) {
    ArRobotPacket p;
    while (state == State.SYNC && (p = intake.poll()) != null) {
      int id = p.getID();
      if (PacketIds.isStandardSip(id)) {
        log.info("robot is still open from an earlier connection: closing it first");
        sender.comInt(ArCommands.CLOSE.getNumber(), 1);
        state = State.CLOSING_OLD;
        deadline = now + CLOSE_OLD_NANOS;
        return false;
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
      identity = new Identity(name, type, subtype);
      state = State.PRE_OPEN;
      deadline = now + cycleNanos;
      return true;
    }
    if (state == State.SYNC && now - sentAt >= REPLY_NANOS) {
      noPacketCount++;
      if ((noPacketCount > 5 && noPacketCount >= timesTried) || noPacketCount > 10) {
        fail("no robot is responding: check the cable, that the robot is on, and the port");
        return false;
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
    return false;
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

  private void configStep(long now, Heard heard) {
    if (heard.config() == null && now - sentAt < CONFIG_NANOS) {
      return;
    }
    // The link sets the speed limits, then steps again for the baud switch.
    state = State.CONFIGURED;
  }

  private void switchBaud(ArDeviceConnection conn, long now, Heard heard) {
    ArConfigPacket config = heard.config();
    int baud = heard.switchToBaudRate();
    boolean robotCanResetBaud =
        config != null && config.getInt(ArConfigPacket.Field.RESET_BAUD) != 0;
    if (baud > 0 && robotCanResetBaud && conn instanceof ArSerialConnection serial) {
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

  private void baudStep(ArDeviceConnection conn, long now, Heard heard) {
    if (heard.packetArrived()) {
      state = State.DONE;
    } else if (now - sentAt > BAUD_NANOS) {
      log.info("robot did not switch baud rate; going back to {}", startBaud);
      ((ArSerialConnection) conn).setBaud(startBaud);
      state = State.DONE;
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
