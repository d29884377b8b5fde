package org.jaria.robot;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Builds command packets and writes them to the robot's connection (ARIA's {@code
 * ArRobotPacketSender}). Safe to call from any thread: one command is written at a time, whole.
 *
 * <p>Each method returns whether the command went out; it does not go out when there is no open
 * connection or the write fails (the failure is logged, and the robot notices the broken connection
 * on its next read).
 */
public final class ArRobotPacketSender {

  private static final Logger log = LoggerFactory.getLogger(ArRobotPacketSender.class);

  private final Clock clock;

  @GuardedBy("this")
  private final ArRobotPacket packet = new ArRobotPacket();

  private final AtomicLong packetsSent = new AtomicLong();
  private volatile ArDeviceConnection connection;
  private volatile long lastSentNanos;
  private volatile Consumer<ArRobotPacket> tap;

  /** A sender timed by {@code clock}, with no connection yet. */
  public ArRobotPacketSender(Clock clock) {
    this.clock = clock;
  }

  /** Sets the connection commands are written to (null for none). */
  public void setDeviceConnection(ArDeviceConnection c) {
    connection = c;
  }

  /** The connection commands are written to. */
  public ArDeviceConnection getDeviceConnection() {
    return connection;
  }

  /**
   * Sets a listener that sees every packet just before it is written (for logging, debugging and
   * tests). It runs on the sending thread and must be quick.
   */
  public void setTap(Consumer<ArRobotPacket> listener) {
    tap = listener;
  }

  /** Sends a command without argument. */
  public synchronized boolean com(int command) {
    return send(CommandCodec.com(packet, command));
  }

  /** Sends a command with an integer argument. */
  public synchronized boolean comInt(int command, int argument) {
    return send(CommandCodec.comInt(packet, command, argument));
  }

  /** Sends a command with two bytes packed in one integer. */
  public synchronized boolean com2Bytes(int command, int high, int low) {
    return send(CommandCodec.com2Bytes(packet, command, high, low));
  }

  /** Sends a command with a string argument. */
  public synchronized boolean comStr(int command, String argument) {
    return send(CommandCodec.comStr(packet, command, argument));
  }

  /** Sends a command with exactly {@code size} bytes of {@code argument}. */
  public synchronized boolean comStrN(int command, String argument, int size) {
    return send(CommandCodec.comStrN(packet, command, argument, size));
  }

  /** Sends a command with raw bytes as its string argument. */
  public synchronized boolean comDataN(int command, byte[] data, int off, int len) {
    return send(CommandCodec.comDataN(packet, command, data, off, len));
  }

  /** Sends a packet the caller built and finalized. */
  public synchronized boolean sendPacket(ArRobotPacket p) {
    return send(p);
  }

  private boolean send(ArRobotPacket p) {
    ArDeviceConnection c = connection;
    if (c == null || c.getStatus() != ArDeviceConnection.Status.OPEN) {
      return false;
    }
    Consumer<ArRobotPacket> t = tap;
    if (t != null) {
      t.accept(p);
    }
    try {
      c.write(p.getBuf(), 0, p.getLength());
    } catch (IOException e) {
      log.warn("could not send command {} to {}: {}", p.getID(), c.getPortName(), e.getMessage());
      return false;
    }
    lastSentNanos = clock.nanoTime();
    packetsSent.incrementAndGet();
    return true;
  }

  /** Clock time the last packet went out (0 if none yet). */
  public long getLastSentNanos() {
    return lastSentNanos;
  }

  /** Packets written so far. */
  public long getPacketsSent() {
    return packetsSent.get();
  }
}
