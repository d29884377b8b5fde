package org.jaria.clock;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.PriorityQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.Lock;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;

/**
 * A clock that stands still until someone calls {@link #advance}. Tests and the simulator's
 * lockstep mode use it so that robot time is independent of how fast the machine is: a minute of
 * robot time passes as fast as the code can run, and the same inputs always give the same run.
 *
 * <p>Threads that sleep or wait with a deadline on this clock are woken by {@link #advance} when
 * the virtual time reaches their deadline, never by the passing of real time.
 */
public final class VirtualClock implements Clock {

  /** A thread waiting for a deadline: who to signal when the time comes. */
  private record Waiter(long deadline, long seq, Lock lock, Condition condition) {}

  private final Object monitor = new Object();
  private final PriorityQueue<Waiter> waiters =
      new PriorityQueue<>(
          (a, b) ->
              a.deadline != b.deadline
                  ? Long.compare(a.deadline, b.deadline)
                  : Long.compare(a.seq, b.seq));
  private volatile long now;
  private long seq;

  /** A clock starting at time zero. */
  public VirtualClock() {
    this(0);
  }

  /** A clock starting at {@code startNanos}. */
  public VirtualClock(long startNanos) {
    this.now = startNanos;
  }

  @Override
  public long nanoTime() {
    return now;
  }

  /** Moves time forward by {@code nanos} and wakes every waiter whose deadline has come. */
  public void advance(long nanos) {
    if (nanos < 0) {
      throw new IllegalArgumentException("time cannot go backwards: advance(" + nanos + ")");
    }
    advanceTo(now + nanos);
  }

  /** Moves time forward by {@code duration}. */
  public void advance(Duration duration) {
    advance(duration.toNanos());
  }

  /** Moves time forward by {@code millis} milliseconds. */
  public void advanceMillis(long millis) {
    advance(millis * 1_000_000L);
  }

  /**
   * Moves time forward to {@code target} (no-op if time is already past it) and wakes every waiter
   * whose deadline is at or before the new time, earliest first.
   */
  public void advanceTo(long target) {
    List<Waiter> due = new ArrayList<>();
    synchronized (monitor) {
      if (target > now) {
        now = target;
      }
      while (!waiters.isEmpty() && waiters.peek().deadline <= now) {
        due.add(waiters.poll());
      }
    }
    for (Waiter w : due) {
      w.lock.lock();
      try {
        w.condition.signalAll();
      } finally {
        w.lock.unlock();
      }
    }
  }

  /** The earliest deadline any thread is waiting for, or {@link Long#MAX_VALUE} if none. */
  public long nextDeadline() {
    synchronized (monitor) {
      Waiter w = waiters.peek();
      return w == null ? Long.MAX_VALUE : w.deadline;
    }
  }

  /** How many threads are currently waiting on this clock with a deadline. */
  public int waitingCount() {
    synchronized (monitor) {
      return waiters.size();
    }
  }

  /**
   * Blocks until at least {@code n} threads are waiting on this clock, or {@code timeout} of real
   * time has passed. A test that drives other threads on virtual time calls it to know they have
   * done their work and parked before it advances the clock; the timeout only keeps a broken test
   * from hanging, it is not part of the synchronisation.
   *
   * @return whether {@code n} threads were waiting
   * @throws InterruptedException if the calling thread is interrupted
   */
  public boolean awaitWaiters(int n, Duration timeout) throws InterruptedException {
    return awaitWaiters(n, timeout, () -> false);
  }

  /**
   * As {@link #awaitWaiters(int, Duration)}, but also returns, with false, as soon as {@code
   * orUntil} is true. Whoever makes it true must then call {@link #wakeWatchers()} (for example a
   * thread that ends instead of waiting on the clock).
   */
  public boolean awaitWaiters(int n, Duration timeout, BooleanSupplier orUntil)
      throws InterruptedException {
    long end = System.nanoTime() + timeout.toNanos();
    synchronized (monitor) {
      while (waiters.size() < n) {
        if (orUntil.getAsBoolean()) {
          return false;
        }
        long left = end - System.nanoTime();
        if (left <= 0) {
          return false;
        }
        TimeUnit.NANOSECONDS.timedWait(monitor, left);
      }
      return true;
    }
  }

  /** Wakes the threads in {@link #awaitWaiters} so they check their condition again. */
  public void wakeWatchers() {
    synchronized (monitor) {
      monitor.notifyAll();
    }
  }

  @Override
  public void sleepNanos(long nanos) throws InterruptedException {
    long deadline = now + Math.max(0, nanos);
    Lock lock = new ReentrantLock();
    Condition condition = lock.newCondition();
    lock.lock();
    try {
      while (awaitUntil(lock, condition, deadline)) {
        // woken before the deadline (spuriously): keep waiting
      }
    } finally {
      lock.unlock();
    }
  }

  @Override
  @SuppressWarnings("WaitNotInLoop") // callers loop, as the interface documents
  public boolean awaitUntil(Lock lock, Condition condition, long deadlineNanos)
      throws InterruptedException {
    Waiter w;
    synchronized (monitor) {
      if (deadlineNanos <= now) {
        return false;
      }
      w = new Waiter(deadlineNanos, seq++, lock, condition);
      waiters.add(w);
      monitor.notifyAll(); // for awaitWaiters
    }
    try {
      condition.await();
    } finally {
      synchronized (monitor) {
        waiters.remove(w);
      }
    }
    return deadlineNanos > now;
  }

  @Override
  public String toString() {
    return "VirtualClock[" + Duration.ofNanos(now) + "]";
  }
}
