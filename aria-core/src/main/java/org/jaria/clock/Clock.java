package org.jaria.clock;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.Lock;

/**
 * The time source for everything in JAria that waits or times out.
 *
 * <p>Robot code never calls {@link System#nanoTime()} or {@link Thread#sleep(long)} directly: it
 * asks its clock. In a program that drives a real robot the clock is {@link SystemClock}; in a test
 * the clock is a {@link VirtualClock} that only moves when the test (or the simulator) advances it,
 * so a minute of robot time can pass in a few milliseconds and every run is identical.
 *
 * <p>Times are in nanoseconds on a monotonic scale whose origin is arbitrary (like {@link
 * System#nanoTime()}); only differences between two readings of the same clock mean anything.
 */
public interface Clock {

  /** Current time in nanoseconds on this clock's monotonic scale. */
  long nanoTime();

  /** Current time in milliseconds on this clock's monotonic scale. */
  default long millis() {
    return TimeUnit.NANOSECONDS.toMillis(nanoTime());
  }

  /**
   * Blocks the calling thread until this clock has advanced by {@code nanos}.
   *
   * @throws InterruptedException if the thread is interrupted while waiting
   */
  void sleepNanos(long nanos) throws InterruptedException;

  /** Blocks the calling thread until this clock has advanced by {@code millis}. */
  default void sleepMillis(long millis) throws InterruptedException {
    sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis));
  }

  /**
   * Waits on {@code condition} until it is signalled or this clock reaches {@code deadlineNanos}.
   * The caller must hold {@code lock}, exactly as for {@link Condition#await()}; like that method,
   * this one may return early (a spurious wake-up), so callers wait in a loop that re-checks their
   * predicate.
   *
   * @return {@code false} if the deadline had passed when the method returned, else {@code true}
   * @throws InterruptedException if the thread is interrupted while waiting
   */
  boolean awaitUntil(Lock lock, Condition condition, long deadlineNanos)
      throws InterruptedException;

  /** The real clock, backed by {@link System#nanoTime()}. */
  static Clock system() {
    return SystemClock.INSTANCE;
  }
}
