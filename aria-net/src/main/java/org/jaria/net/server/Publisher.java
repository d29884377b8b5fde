package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thread that serves requests at an interval (ArNetworking's REQUEST): every few milliseconds
 * it looks for requests that are due, takes each published value once (encoded once per version,
 * shared by every client), and queues an update for every due subscription whose client has not
 * seen that version. Queuing coalesces, so a client that reads slowly simply gets fewer, newer
 * updates. Subscription rates are timed by the real clock: the network is real even when the robot
 * runs on virtual time.
 */
final class Publisher implements Runnable {

  private static final Logger log = LoggerFactory.getLogger(Publisher.class);

  /** How often due subscriptions are looked for. */
  private static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(5);

  private final ArServerBase server;
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition wake = lock.newCondition();

  @GuardedBy("lock")
  private boolean woken;

  private volatile boolean stopping;
  private long failures;

  Publisher(ArServerBase server) {
    this.server = server;
  }

  /** Makes the thread look at once (a new subscription). */
  void wakeup() {
    lock.lock();
    try {
      woken = true;
      wake.signalAll();
    } finally {
      lock.unlock();
    }
  }

  void stop() {
    stopping = true;
    wakeup();
  }

  @Override
  public void run() {
    Map<DataEntry, DataEntry.Encoded> tick = new HashMap<>();
    while (!stopping) {
      try {
        publishDue(tick);
        tick.clear();
        lock.lock();
        try {
          if (!woken && !stopping) {
            wake.awaitNanos(TICK_NANOS);
          }
          woken = false;
        } finally {
          lock.unlock();
        }
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        return;
      } catch (RuntimeException e) {
        if (++failures == 1 || failures % 100 == 0) {
          log.warn("publishing failed (#{}): {}", failures, e.toString(), e);
        }
      }
    }
  }

  private void publishDue(Map<DataEntry, DataEntry.Encoded> tick) {
    long now = System.nanoTime();
    long minNanos = server.getOptions().minInterval().toNanos();
    boolean any = false;
    for (ArServerClient c : server.clientsSnapshot()) {
      if (!c.isLoggedIn() || c.closeAfterFlush) {
        continue;
      }
      boolean queued = false;
      for (ArServerClient.Request s : c.requests.values()) {
        if (now - s.nextDueNanos < 0) {
          continue;
        }
        // A request "when it changes" (-1) is looked at every minimum interval.
        long interval = s.periodic() ? s.intervalNanos : minNanos;
        // Keep the phase, but never try to catch up on missed intervals.
        s.nextDueNanos = Math.max(s.nextDueNanos + interval, now);
        if (s.entry.publication == null) {
          // A handler requested at an interval runs again (if its last run has finished).
          if (s.periodic() && s.running.compareAndSet(false, true)) {
            c.pendingCalls.incrementAndGet();
            server.execute(c, s.entry, s.args, s);
          }
          continue;
        }
        DataEntry.Encoded e = tick.computeIfAbsent(s.entry, this::encode);
        if (e == null || e.version() == s.lastVersion) {
          continue;
        }
        s.lastVersion = e.version();
        c.out.offerUpdate(Outgoing.update(s.entry.id(), e.version(), e.wire()));
        server.stats.updatesQueued.increment();
        queued = true;
      }
      if (queued) {
        server.io().scheduleWrite(c, false);
        any = true;
      }
    }
    if (any) {
      server.io().wakeup();
    }
  }

  private DataEntry.Encoded encode(DataEntry d) {
    try {
      return d.currentEncoded();
    } catch (RuntimeException e) {
      if (++failures == 1 || failures % 100 == 0) {
        log.warn("{} could not be published (#{}): {}", d.name(), failures, e.toString());
      }
      return null;
    }
  }
}
