package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Consumer;

/**
 * The work waiting for the robot's cycle, in the order it arrived, with the {@link CallPolicy}
 * rules: a newer {@link CallPolicy#LATEST_WINS} request replaces the one of the same key still
 * waiting; a {@link CallPolicy#SAFETY} request is always taken and is applied at the next drain
 * before everything else, after the work that arrived before it (minus the latest-wins requests it
 * makes pointless); work of an earlier request that arrives after a safety request was applied is
 * followed by that safety request again (or dropped if something newer has been applied since).
 *
 * <p>Every request carries a sequence number in arrival order; work that is not a request carries
 * {@link #NOT_A_REQUEST}. Any thread may offer; only the robot's cycle thread drains.
 */
final class CycleQueue {

  /** The sequence number of work that is no client's request (never older than a stop). */
  static final long NOT_A_REQUEST = Long.MAX_VALUE;

  /**
   * One piece of work: what to run, what to do if a newer request replaces it before it ran, and
   * how to apply it again without answering anybody (safety requests only).
   */
  record Work(Runnable run, Runnable superseded, Runnable reassert) {

    /** Plain work: nothing to do if superseded, nothing to apply again. */
    static Work of(Runnable r) {
      return new Work(r, () -> {}, () -> {});
    }
  }

  private static final class Entry {
    final Object key;
    final CallPolicy policy;
    long seq;
    Work work;

    Entry(Object key, CallPolicy policy, long seq, Work work) {
      this.key = key;
      this.policy = policy;
      this.seq = seq;
      this.work = work;
    }
  }

  private final int capacity;
  private final Object lock = new Object();

  @GuardedBy("lock")
  private final ArrayDeque<Entry> queue = new ArrayDeque<>();

  @GuardedBy("lock")
  private final List<Entry> safety = new ArrayList<>();

  /** The latest-wins and safety entries waiting, by key. */
  @GuardedBy("lock")
  private final Map<Object, Entry> waitingByKey = new HashMap<>();

  /** Queued entries counted against the capacity (latest-wins and safety are not). */
  @GuardedBy("lock")
  private int counted;

  // The cycle thread only.
  private Work lastSafety;
  private long lastSafetySeq = Long.MIN_VALUE;
  private long newestApplied = Long.MIN_VALUE;

  private final LongAdder superseded;
  private final LongAdder reasserted;

  /**
   * A queue taking at most {@code capacity} plain requests and work at once, counting the requests
   * replaced or dropped before they ran in {@code superseded} and the times a safety request was
   * applied again in {@code reasserted}.
   */
  CycleQueue(int capacity, LongAdder superseded, LongAdder reasserted) {
    this.capacity = capacity;
    this.superseded = superseded;
    this.reasserted = reasserted;
  }

  /** Queues plain work; false if {@code capacity} are already waiting. */
  boolean offer(Work w, long seq) {
    synchronized (lock) {
      if (counted >= capacity) {
        return false;
      }
      counted++;
      queue.add(new Entry(null, CallPolicy.QUEUED, seq, w));
      return true;
    }
  }

  /** Queues a latest-wins request: replaces the one of {@code key} still waiting, if any. */
  void offerLatest(Object key, Work w, long seq) {
    Work replaced = null;
    synchronized (lock) {
      Entry e = waitingByKey.get(key);
      if (e != null && e.policy == CallPolicy.LATEST_WINS) {
        replaced = e.work;
        e.work = w;
        e.seq = seq;
      } else {
        e = new Entry(key, CallPolicy.LATEST_WINS, seq, w);
        waitingByKey.put(key, e);
        queue.add(e);
      }
    }
    if (replaced != null) {
      superseded.increment();
      replaced.superseded().run();
    }
  }

  /** Queues a safety request; one of {@code key} still waiting is replaced by it. */
  void offerSafety(Object key, Work w, long seq) {
    Work replaced = null;
    synchronized (lock) {
      Entry e = waitingByKey.get(key);
      if (e != null && e.policy == CallPolicy.SAFETY) {
        replaced = e.work;
        e.work = w;
        e.seq = seq;
      } else {
        e = new Entry(key, CallPolicy.SAFETY, seq, w);
        waitingByKey.put(key, e);
        safety.add(e);
      }
    }
    if (replaced != null) {
      superseded.increment();
      replaced.superseded().run();
    }
  }

  /** Work waiting. */
  int size() {
    synchronized (lock) {
      return queue.size() + safety.size();
    }
  }

  /** Forgets everything waiting (the server is closing). */
  void clear() {
    synchronized (lock) {
      queue.clear();
      safety.clear();
      waitingByKey.clear();
      counted = 0;
    }
  }

  /**
   * Runs, on the robot's cycle, the waiting safety requests (with what arrived before them), then
   * at most {@code max} other pieces of work, each through {@code runner}.
   */
  void drain(int max, Consumer<Runnable> runner) {
    applySafety(runner);
    for (int i = 0; i < max; i++) {
      Entry e;
      synchronized (lock) {
        e = queue.poll();
        if (e == null) {
          return;
        }
        forget(e);
      }
      if (e.seq < lastSafetySeq && lastSafety != null) {
        if (newestApplied > lastSafetySeq) {
          // A stop and then newer commands were applied since this was asked: it is moot.
          superseded.increment();
          runner.accept(e.work.superseded());
          continue;
        }
        runner.accept(e.work.run());
        reasserted.increment();
        runner.accept(lastSafety.reassert());
        continue;
      }
      apply(e, runner);
    }
  }

  private void applySafety(Consumer<Runnable> runner) {
    List<Entry> stops;
    List<Entry> before = new ArrayList<>();
    List<Entry> moot = new ArrayList<>();
    long barrier = Long.MIN_VALUE;
    synchronized (lock) {
      if (safety.isEmpty()) {
        return;
      }
      stops = new ArrayList<>(safety);
      safety.clear();
      for (Entry s : stops) {
        waitingByKey.remove(s.key);
        barrier = Math.max(barrier, s.seq);
      }
      for (Iterator<Entry> it = queue.iterator(); it.hasNext(); ) {
        Entry e = it.next();
        if (e.seq < barrier) {
          it.remove();
          forget(e);
          (e.policy == CallPolicy.LATEST_WINS ? moot : before).add(e);
        }
      }
    }
    for (Entry e : moot) {
      superseded.increment();
      runner.accept(e.work.superseded());
    }
    for (Entry e : before) {
      apply(e, runner);
    }
    for (Entry s : stops) {
      apply(s, runner);
    }
    lastSafety = stops.get(stops.size() - 1).work;
    lastSafetySeq = barrier;
  }

  private void apply(Entry e, Consumer<Runnable> runner) {
    if (e.seq != NOT_A_REQUEST) {
      newestApplied = Math.max(newestApplied, e.seq);
    }
    runner.accept(e.work.run());
  }

  @GuardedBy("lock")
  private void forget(Entry e) {
    if (e.key != null) {
      waitingByKey.remove(e.key, e);
    }
    if (e.policy == CallPolicy.QUEUED) {
      counted--;
    }
  }
}
