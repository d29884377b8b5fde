package org.jaria.clock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.junit.jupiter.api.Test;

class VirtualClockTest {

  /** Waits (in real time, briefly) until {@code n} threads are parked on the clock. */
  private static void awaitWaiters(VirtualClock c, int n) throws InterruptedException {
    long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
    while (c.waitingCount() < n) {
      if (System.nanoTime() > end) {
        throw new AssertionError("only " + c.waitingCount() + " of " + n + " threads waiting");
      }
      Thread.onSpinWait();
    }
  }

  @Test
  void timeMovesOnlyWhenAdvanced() {
    VirtualClock c = new VirtualClock(5);
    assertEquals(5, c.nanoTime());
    c.advanceMillis(2);
    assertEquals(2_000_005, c.nanoTime());
    c.advanceTo(1);
    assertEquals(2_000_005, c.nanoTime());
    assertThrows(IllegalArgumentException.class, () -> c.advance(-1));
  }

  @Test
  void sleepersWakeInDeadlineOrderWhenTimeReachesThem() throws Exception {
    VirtualClock c = new VirtualClock();
    List<String> woke = new CopyOnWriteArrayList<>();
    CountDownLatch done = new CountDownLatch(2);
    Thread a = sleepingThread(c, 300, "a", woke, done);
    Thread b = sleepingThread(c, 100, "b", woke, done);
    a.start();
    b.start();
    awaitWaiters(c, 2);
    assertEquals(100_000_000L, c.nextDeadline());
    c.advanceMillis(99);
    assertEquals(2, c.waitingCount());
    c.advanceMillis(1);
    long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
    while (!woke.contains("b") && System.nanoTime() < end) {
      Thread.onSpinWait(); // b was signalled; let it record that it woke
    }
    assertEquals(List.of("b"), woke);
    c.advanceMillis(500);
    assertTrue(done.await(10, TimeUnit.SECONDS));
    assertEquals(List.of("b", "a"), woke);
    a.join();
    b.join();
  }

  private static Thread sleepingThread(
      VirtualClock c, long ms, String name, List<String> woke, CountDownLatch done) {
    return new Thread(
        () -> {
          try {
            c.sleepMillis(ms);
            woke.add(name);
            done.countDown();
          } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
          }
        },
        "sleeper-" + name);
  }

  @Test
  void awaitUntilReturnsFalseOncePastTheDeadline() throws Exception {
    VirtualClock c = new VirtualClock();
    ReentrantLock lock = new ReentrantLock();
    Condition cond = lock.newCondition();
    lock.lock();
    try {
      assertFalse(c.awaitUntil(lock, cond, 0));
    } finally {
      lock.unlock();
    }
    boolean[] result = new boolean[1];
    Thread t =
        new Thread(
            () -> {
              lock.lock();
              try {
                result[0] = c.awaitUntil(lock, cond, 50);
              } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
              } finally {
                lock.unlock();
              }
            });
    t.start();
    awaitWaiters(c, 1);
    c.advance(50);
    t.join(10_000);
    assertFalse(t.isAlive());
    assertFalse(result[0]);
  }

  @Test
  void signalBeforeTheDeadlineWakesWithTrue() throws Exception {
    VirtualClock c = new VirtualClock();
    ReentrantLock lock = new ReentrantLock();
    Condition cond = lock.newCondition();
    boolean[] result = new boolean[1];
    Thread t =
        new Thread(
            () -> {
              lock.lock();
              try {
                result[0] = c.awaitUntil(lock, cond, 1_000);
              } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
              } finally {
                lock.unlock();
              }
            });
    t.start();
    awaitWaiters(c, 1);
    lock.lock();
    try {
      cond.signalAll();
    } finally {
      lock.unlock();
    }
    t.join(10_000);
    assertTrue(result[0]);
    assertEquals(0, c.waitingCount());
  }
}
