package org.jaria.protocol;

import java.util.concurrent.TimeUnit;

/**
 * Turns a stream of bytes into ARCOS packets.
 *
 * <p>Feed it whatever bytes arrive, in any chunks; it calls the listener once for every packet with
 * a good length and checksum. It never trusts a header blindly: when a candidate packet fails (bad
 * COUNT, bad checksum, or its bytes stop arriving for longer than the timeout) it drops that
 * candidate, counts why, and searches again from the byte after the failed header. So a valid
 * packet is found even when garbage before it looked like the start of a long packet.
 *
 * <p>Nothing is allocated per packet: the listener receives the receiver's own packet object, valid
 * until the listener returns (copy it with {@link ArRobotPacket#copyFrom} to keep it).
 *
 * <p>Not thread-safe: one receiver per connection, used by the one thread that reads it.
 */
public final class ArRobotPacketReceiver {

  /** Receives each good packet. */
  @FunctionalInterface
  public interface Listener {
    /** Called for each packet; {@code packet} is reused after this call returns. */
    void packetReceived(ArRobotPacket packet);
  }

  /** ARIA's time after which a half-received packet is abandoned. */
  public static final long DEFAULT_TIMEOUT_MS = 100;

  private final byte[] buf = new byte[4 * ArRobotPacket.MAX_LENGTH];
  private final ArRobotPacket packet = new ArRobotPacket();
  private final DropCounters drops;
  private final long timeoutNanos;
  private int start;
  private int end;
  private long lastByteNanos;
  private long packetsReceived;

  /** A receiver with ARIA's 100 ms timeout. */
  public ArRobotPacketReceiver(DropCounters drops) {
    this(drops, DEFAULT_TIMEOUT_MS);
  }

  /** A receiver that abandons half-received packets after {@code timeoutMs}. */
  public ArRobotPacketReceiver(DropCounters drops, long timeoutMs) {
    this.drops = drops;
    this.timeoutNanos = TimeUnit.MILLISECONDS.toNanos(timeoutMs);
  }

  /** The counters this receiver records its drops in. */
  public DropCounters drops() {
    return drops;
  }

  /** Good packets delivered so far. */
  public long packetsReceived() {
    return packetsReceived;
  }

  /** Bytes held back because they may be the start of a packet still arriving. */
  public int pendingBytes() {
    return end - start;
  }

  /**
   * Processes {@code len} bytes from {@code data}, received at {@code nowNanos} (on the caller's
   * clock), calling {@code listener} for each complete good packet.
   */
  public void feed(byte[] data, int off, int len, long nowNanos, Listener listener) {
    expire(nowNanos, listener);
    while (len > 0) {
      compact();
      int n = Math.min(len, buf.length - end);
      System.arraycopy(data, off, buf, end, n);
      end += n;
      off += n;
      len -= n;
      parse(listener, false);
    }
    lastByteNanos = nowNanos;
  }

  /**
   * Abandons a half-received packet if no byte has arrived for the timeout. Call this when a read
   * returns nothing, so a truncated packet is counted even if the stream then goes quiet.
   */
  public void checkTimeout(long nowNanos, Listener listener) {
    expire(nowNanos, listener);
  }

  /** Forgets any partial packet (e.g. after reconnecting), counting nothing. */
  public void reset() {
    start = 0;
    end = 0;
  }

  private void expire(long nowNanos, Listener listener) {
    if (end > start && nowNanos - lastByteNanos > timeoutNanos) {
      drops.drop(DropReason.TIMEOUT, (end - start) + " bytes then silence");
      start++;
      drops.skipped(1);
      parse(listener, true);
    }
  }

  private void compact() {
    if (start > 0) {
      System.arraycopy(buf, start, buf, 0, end - start);
      end -= start;
      start = 0;
    }
  }

  /**
   * Extracts every packet in {@code buf[start, end)}. With {@code flush}, an incomplete candidate
   * is garbage (its bytes stopped arriving) instead of something to wait for.
   */
  private void parse(Listener listener, boolean flush) {
    while (end > start) {
      if ((buf[start] & 0xFF) != ArRobotPacket.HEADER1) {
        skip();
        continue;
      }
      int avail = end - start;
      if (avail < 2) {
        if (flush) {
          skip();
          continue;
        }
        return;
      }
      if ((buf[start + 1] & 0xFF) != ArRobotPacket.HEADER2) {
        skip();
        continue;
      }
      if (avail < 3) {
        if (flush) {
          skip();
          continue;
        }
        return;
      }
      int count = buf[start + 2] & 0xFF;
      if (count < ArRobotPacket.MIN_COUNT || count > ArRobotPacket.MAX_COUNT) {
        drops.drop(DropReason.BAD_LENGTH, "count " + count);
        skip();
        continue;
      }
      int total = count + 3;
      if (avail < total) {
        if (flush) {
          skip();
          continue;
        }
        return;
      }
      int sum = ArRobotPacket.checksum(buf, start + 3, count - 2);
      int stored = ((buf[start + total - 2] & 0xFF) << 8) | (buf[start + total - 1] & 0xFF);
      if (sum != stored) {
        drops.drop(DropReason.BAD_CHECKSUM, "id 0x" + Integer.toHexString(buf[start + 3] & 0xFF));
        skip();
        continue;
      }
      packet.load(buf, start, total);
      start += total;
      packetsReceived++;
      listener.packetReceived(packet);
    }
  }

  private void skip() {
    start++;
    drops.skipped(1);
  }
}
