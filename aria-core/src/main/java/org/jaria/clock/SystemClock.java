package org.jaria.clock;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.Lock;

/** The wall clock: {@link System#nanoTime()} and real sleeping. Stateless, so one instance. */
public final class SystemClock implements Clock {

  static final SystemClock INSTANCE = new SystemClock();

  private SystemClock() {}

  @Override
  public long nanoTime() {
    return System.nanoTime();
  }

  @Override
  public void sleepNanos(long nanos) throws InterruptedException {
    if (nanos > 0) {
      TimeUnit.NANOSECONDS.sleep(nanos);
    }
  }

  @Override
  @SuppressWarnings("WaitNotInLoop") // callers loop, as the interface documents
  public boolean awaitUntil(Lock lock, Condition condition, long deadlineNanos)
      throws InterruptedException {
    long remaining = deadlineNanos - System.nanoTime();
    if (remaining <= 0) {
      return false;
    }
    condition.awaitNanos(remaining);
    return deadlineNanos - System.nanoTime() > 0;
  }

  @Override
  public String toString() {
    return "SystemClock";
  }
}
