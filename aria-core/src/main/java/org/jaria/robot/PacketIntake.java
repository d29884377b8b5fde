package org.jaria.robot;

import java.io.EOFException;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.PacketIds;

/**
 * Reads bytes from the robot's connection and queues the packets they form, without allocating: the
 * queue is a ring of preallocated packets. Used only by the thread that runs the robot's cycle (or
 * connects it), so it needs no locking.
 *
 * <p>If the program falls so far behind that the ring fills, the oldest packet is dropped and
 * counted ({@link DropReason#OVERFLOW}): fresh data is worth more than stale data to a robot.
 */
final class PacketIntake {

  private static final int CAPACITY = 256;

  private final ArRobotPacket[] ring = new ArRobotPacket[CAPACITY];
  private final byte[] readBuf = new byte[4096];
  private final DropCounters drops;
  private final ArRobotPacketReceiver receiver;
  private final ArRobotPacketReceiver.Listener enqueue = this::enqueue;
  private int head;
  private int size;
  private int sipsQueued;
  private long lastPacketNanos;
  private long nowNanos;

  PacketIntake(DropCounters drops) {
    this.drops = drops;
    this.receiver = new ArRobotPacketReceiver(drops);
    for (int i = 0; i < CAPACITY; i++) {
      ring[i] = new ArRobotPacket();
    }
  }

  DropCounters drops() {
    return drops;
  }

  /** Clock time the last good packet arrived. */
  long lastPacketNanos() {
    return lastPacketNanos;
  }

  /** Marks "now" as the time of the last packet (at connect, so the timeout starts fresh). */
  void touch(long now) {
    lastPacketNanos = now;
  }

  /** Forgets queued packets and partial input. */
  void clear() {
    head = 0;
    size = 0;
    sipsQueued = 0;
    receiver.reset();
  }

  /** Whether a standard SIP is waiting in the queue. */
  boolean hasSip() {
    return sipsQueued > 0;
  }

  /** Whether any packet is waiting. */
  boolean hasPacket() {
    return size > 0;
  }

  /**
   * Takes the oldest queued packet, or null. The packet stays valid until the queue wraps around to
   * it again (more than 200 packets later), so use it before reading again.
   */
  ArRobotPacket poll() {
    if (size == 0) {
      return null;
    }
    ArRobotPacket p = ring[head];
    head = (head + 1) % CAPACITY;
    size--;
    if (PacketIds.isStandardSip(p.getID())) {
      sipsQueued--;
    }
    p.resetRead();
    return p;
  }

  /**
   * Reads whatever has arrived, without waiting.
   *
   * @throws IOException if the connection failed or the other end closed it
   */
  void readAvailable(ArDeviceConnection c, long now) throws IOException {
    nowNanos = now;
    while (true) {
      int n = c.read(readBuf, 0, readBuf.length, 0);
      if (n < 0) {
        throw new EOFException(c.getPortName() + ": the robot closed the connection");
      }
      if (n == 0) {
        receiver.checkTimeout(now, enqueue);
        return;
      }
      feed(n, now);
    }
  }

  /**
   * Reads until a standard SIP is queued or the clock reaches {@code deadline}.
   *
   * @throws IOException if the connection failed or the other end closed it
   */
  void waitForSip(ArDeviceConnection c, Clock clock, long deadline) throws IOException {
    waitFor(c, clock, deadline, true);
  }

  /** Reads until any packet is queued or the clock reaches {@code deadline}. */
  void waitForPacket(ArDeviceConnection c, Clock clock, long deadline) throws IOException {
    waitFor(c, clock, deadline, false);
  }

  private void waitFor(ArDeviceConnection c, Clock clock, long deadline, boolean sipOnly)
      throws IOException {
    while (sipOnly ? sipsQueued == 0 : size == 0) {
      long now = clock.nanoTime();
      long remaining = deadline - now;
      if (remaining <= 0) {
        return;
      }
      long ms = Math.max(1, TimeUnit.NANOSECONDS.toMillis(remaining));
      int n = c.read(readBuf, 0, readBuf.length, ms);
      now = clock.nanoTime();
      if (n < 0) {
        throw new EOFException(c.getPortName() + ": the robot closed the connection");
      }
      if (n == 0) {
        nowNanos = now;
        receiver.checkTimeout(now, enqueue);
      } else {
        feed(n, now);
      }
    }
  }

  private void feed(int n, long now) {
    nowNanos = now;
    receiver.feed(readBuf, 0, n, now, enqueue);
  }

  private void enqueue(ArRobotPacket p) {
    if (size == CAPACITY) {
      ArRobotPacket dropped = poll();
      drops.drop(DropReason.OVERFLOW, "id 0x" + Integer.toHexString(dropped.getID()));
    }
    ring[(head + size) % CAPACITY].copyFrom(p);
    size++;
    if (PacketIds.isStandardSip(p.getID())) {
      sipsQueued++;
    }
    lastPacketNanos = nowNanos;
  }
}
