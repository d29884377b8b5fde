package org.jaria.protocol;

import java.util.EnumMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLongArray;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Counts dropped packets by reason and skipped garbage bytes, and logs them without flooding the
 * log: the 1st, 10th, 100th, ... drop of each reason is logged. Safe to read from any thread.
 */
public final class DropCounters {

  private static final Logger log = LoggerFactory.getLogger(DropCounters.class);

  private final String source;
  private final AtomicLongArray drops = new AtomicLongArray(DropReason.values().length);
  private final AtomicLongArray skipped = new AtomicLongArray(1);

  /** Counters labelled with {@code source} in log messages (e.g. the connection's name). */
  public DropCounters(String source) {
    this.source = source;
  }

  /** Records one dropped packet; {@code detail} is only used if this drop gets logged. */
  public void drop(DropReason reason, String detail) {
    long n = drops.incrementAndGet(reason.ordinal());
    if (isPowerOfTen(n)) {
      log.warn("{}: dropped packet #{} for {} ({})", source, n, reason, detail);
    }
  }

  /** Records one dropped packet. */
  public void drop(DropReason reason) {
    drop(reason, "");
  }

  /** Records {@code n} bytes skipped while looking for a packet header. */
  public void skipped(int n) {
    skipped.addAndGet(0, n);
  }

  /** Packets dropped for {@code reason} so far. */
  public long get(DropReason reason) {
    return drops.get(reason.ordinal());
  }

  /** Packets dropped for any reason so far. */
  public long total() {
    long t = 0;
    for (int i = 0; i < drops.length(); i++) {
      t += drops.get(i);
    }
    return t;
  }

  /** Bytes skipped while hunting for a header (garbage between packets). */
  public long skippedBytes() {
    return skipped.get(0);
  }

  /** A snapshot of all counts by reason. */
  public Map<DropReason, Long> snapshot() {
    Map<DropReason, Long> m = new EnumMap<>(DropReason.class);
    for (DropReason r : DropReason.values()) {
      m.put(r, get(r));
    }
    return m;
  }

  private static boolean isPowerOfTen(long n) {
    while (n >= 10 && n % 10 == 0) {
      n /= 10;
    }
    return n == 1;
  }

  @Override
  public String toString() {
    return source + " drops " + snapshot() + ", skipped bytes " + skippedBytes();
  }
}
