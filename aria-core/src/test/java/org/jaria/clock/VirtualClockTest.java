package org.jaria.clock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.junit.jupiter.api.Test;

class VirtualClockTest {

  /** Waits until {@code n} threads are parked on the clock (real time bounds a broken test). */
  private static void awaitWaiters(VirtualClock c, int n) throws InterruptedException {
    assertTrue(
        c.awaitWaiters(n, Duration.ofSeconds(10)),
        "only " + c.waitingCount() + " of " + n + " threads waiting");
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
    CountDownLatch aDone = new CountDownLatch(1);
    CountDownLatch bDone = new CountDownLatch(1);
    Thread a = sleepingThread(c, 300, "a", woke, aDone);
    Thread b = sleepingThread(c, 100, "b", woke, bDone);
    a.start();
    b.start();
    awaitWaiters(c, 2);
    assertEquals(100_000_000L, c.nextDeadline());
    c.advanceMillis(99);
    assertEquals(2, c.waitingCount());
    c.advanceMillis(1);
    assertTrue(bDone.await(10, TimeUnit.SECONDS), "b was signalled and recorded that it woke");
    assertEquals(List.of("b"), woke);
    assertEquals(1, aDone.getCount(), "a still sleeps");
    c.advanceMillis(500);
    assertTrue(aDone.await(10, TimeUnit.SECONDS));
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
            },
            "awaiter-deadline");
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
            },
            "awaiter-signal");
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

  @Test
  void awaitWaitersGivesUpAfterItsTimeoutWhenNobodyWaits() throws Exception {
    VirtualClock c = new VirtualClock();
    assertTrue(c.awaitWaiters(0, Duration.ZERO));
    assertFalse(c.awaitWaiters(1, Duration.ofMillis(1)), "nobody waits on this clock");
  }
}
