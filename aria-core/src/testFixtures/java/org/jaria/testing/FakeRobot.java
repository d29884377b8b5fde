package org.jaria.testing;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.StandardSip;

/**
 * A scripted ARCOS robot for client tests: it answers the handshake like a real robot, replies to
 * CONFIG, and records every packet the client sends with the (virtual) time it arrived. It does no
 * physics: tests choose what SIPs to send. Driven by hand ({@link #pump}) so a test controls time.
 */
public final class FakeRobot {

  /** A packet the client sent, with the time the fake robot read it. */
  public record Received(long timeNanos, int id, String hex, int intArg) {
    /** The command, or null if the number is unknown. */
    public ArCommands command() {
      return ArCommands.fromNumber(id);
    }
  }

  private final ArDeviceConnection conn;
  private final Clock clock;
  private final ArRobotPacketReceiver receiver =
      new ArRobotPacketReceiver(new DropCounters("fake-robot"));
  private final List<Received> received = new ArrayList<>();
  private final ArRobotPacket out = new ArRobotPacket();
  private final byte[] buf = new byte[4096];
  private String name = "fake";
  private String type = "Pioneer";
  private String subtype = "p3dx-sh";
  private boolean open;
  private boolean answerSync = true;
  private boolean answerConfig = true;
  private int syncExpected;

  /** A fake robot on the server end of a connection. */
  public FakeRobot(ArDeviceConnection serverEnd, Clock clock) {
    this.conn = serverEnd;
    this.clock = clock;
  }

  /** Sets the identity answered to SYNC2. */
  public FakeRobot identity(String robotName, String robotType, String robotSubtype) {
    name = robotName;
    type = robotType;
    subtype = robotSubtype;
    return this;
  }

  /** Whether the fake answers SYNC packets at all (false: a dead robot). */
  public FakeRobot answerSync(boolean on) {
    answerSync = on;
    return this;
  }

  /** Whether the fake answers CONFIG. */
  public FakeRobot answerConfig(boolean on) {
    answerConfig = on;
    return this;
  }

  /** Pretends an earlier client left the robot open (it streams SIPs and ignores SYNCs). */
  public FakeRobot alreadyOpen() {
    open = true;
    return this;
  }

  /** Whether the client has opened the robot (and not closed it). */
  public boolean isOpen() {
    return open;
  }

  /** Every packet received so far. */
  public List<Received> received() {
    return List.copyOf(received);
  }

  /** Forgets the packets received so far. */
  public void clearReceived() {
    received.clear();
  }

  /** Received packets with this command number. */
  public List<Received> received(ArCommands c) {
    List<Received> r = new ArrayList<>();
    for (Received x : received) {
      if (x.id() == c.getNumber()) {
        r.add(x);
      }
    }
    return r;
  }

  /** Reads what the client sent and answers it. */
  public void pump() throws IOException {
    int n;
    while ((n = conn.read(buf, 0, buf.length, 0)) > 0) {
      receiver.feed(buf, 0, n, clock.nanoTime(), this::handle);
    }
  }

  /**
   * Waits up to {@code timeoutMs} for the client to send something, then reads and answers all of
   * it.
   *
   * @return false if the client closed the connection
   */
  public boolean pumpWait(long timeoutMs) throws IOException {
    int n = conn.read(buf, 0, buf.length, timeoutMs);
    if (n < 0) {
      return false;
    }
    if (n > 0) {
      receiver.feed(buf, 0, n, clock.nanoTime(), this::handle);
    }
    pump();
    return true;
  }

  /** How many packets have been received so far. */
  public int receivedCount() {
    return received.size();
  }

  /** The {@code i}-th packet received. */
  public Received received(int i) {
    return received.get(i);
  }

  private void handle(ArRobotPacket p) {
    int id = p.getID();
    int arg = CommandCodec.readIntArg(p, Integer.MIN_VALUE);
    received.add(new Received(clock.nanoTime(), id, p.toHexString(), arg));
    try {
      if (!open) {
        handleSync(id);
      } else if (id == ArCommands.CLOSE.getNumber()) {
        open = false;
        syncExpected = 0;
      } else if (id == ArCommands.CONFIG.getNumber() && answerConfig) {
        send(config());
      }
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
  }

  private void handleSync(int id) throws IOException {
    if (!answerSync) {
      return;
    }
    if (id == ArCommands.OPEN.getNumber() && syncExpected == 3) {
      open = true;
      return;
    }
    if (id > 2) {
      return;
    }
    if (id != syncExpected) {
      syncExpected = 0;
      if (id != 0) {
        return;
      }
    }
    out.empty().setID(id);
    if (id == 2) {
      out.strToBuf(name).strToBuf(type).strToBuf(subtype);
    }
    send(out.finalizePacket());
    syncExpected = id + 1;
  }

  private ArRobotPacket config() {
    ArConfigPacket c = new ArConfigPacket();
    c.set(ArConfigPacket.Field.TYPE, type).set(ArConfigPacket.Field.SUBTYPE, subtype);
    c.set(ArConfigPacket.Field.SERIAL_NUMBER, "FAKE").set(ArConfigPacket.Field.NAME, name);
    c.set(ArConfigPacket.Field.ROT_VEL_TOP, 360).set(ArConfigPacket.Field.TRANS_VEL_TOP, 1500);
    c.set(ArConfigPacket.Field.ROT_ACCEL_TOP, 300).set(ArConfigPacket.Field.TRANS_ACCEL_TOP, 2000);
    c.set(ArConfigPacket.Field.TRANS_VEL_MAX, 750).set(ArConfigPacket.Field.ROT_VEL_MAX, 100);
    c.set(ArConfigPacket.Field.TRANS_ACCEL, 300).set(ArConfigPacket.Field.TRANS_DECEL, 300);
    c.set(ArConfigPacket.Field.ROT_ACCEL, 100).set(ArConfigPacket.Field.ROT_DECEL, 100);
    c.set(ArConfigPacket.Field.SIP_CYCLE_TIME, 100).set(ArConfigPacket.Field.WATCHDOG, 2000);
    c.set(ArConfigPacket.Field.FIRMWARE_VERSION, "F.1");
    return c.encode(new ArRobotPacket());
  }

  /** Sends a standard SIP (only meaningful once open, but sent regardless). */
  public void sendSip(StandardSip sip) throws IOException {
    send(sip.encode(out));
  }

  /** Sends any packet. */
  public void send(ArRobotPacket p) throws IOException {
    conn.write(p.getBuf(), 0, p.getLength());
  }

  /** Sends raw bytes (garbage, truncated packets ...). */
  public void sendRaw(byte[] bytes) throws IOException {
    conn.write(bytes, 0, bytes.length);
  }
}
