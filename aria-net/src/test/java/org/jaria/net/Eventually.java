package org.jaria.net;

import static org.junit.jupiter.api.Assertions.fail;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

/**
 * Waits for something another thread (the server's I/O or publisher thread, a client's reader)
 * makes true: the condition is checked every fraction of a millisecond until it holds, and the test
 * fails with {@code what} if it has not after a generous real-time bound. Never a timing assertion:
 * a fast machine passes sooner, a loaded one later.
 */
public final class Eventually {

  /** Bound for anything the network does on this machine. */
  public static final Duration LIMIT = Duration.ofSeconds(20);

  private Eventually() {}

  /** Waits until {@code condition} holds; fails naming {@code what} otherwise. */
  public static void until(String what, BooleanSupplier condition) {
    if (!holdsWithin(condition, LIMIT)) {
      fail("not within " + LIMIT.toSeconds() + " s: " + what);
    }
  }

  /** Waits until {@code condition} holds, at most {@code max}; returns whether it did. */
  public static boolean holdsWithin(BooleanSupplier condition, Duration max) {
    long end = System.nanoTime() + max.toNanos();
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - end > 0) {
        return false;
      }
      LockSupport.parkNanos(200_000);
    }
    return true;
  }

  /** Waits until {@code value} gives a non-null value and returns it. */
  public static <T> T value(String what, Supplier<T> value) {
    Object[] box = new Object[1];
    until(what, () -> (box[0] = value.get()) != null);
    @SuppressWarnings("unchecked")
    T t = (T) box[0];
    return t;
  }
}
