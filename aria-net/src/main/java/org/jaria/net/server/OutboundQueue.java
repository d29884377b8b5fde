package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.Map;

/**
 * What waits to be sent to one client, bounded two ways:
 *
 * <ul>
 *   <li>subscription updates are <em>coalesced</em>: while an update of a subscription is still
 *       waiting, a newer one replaces it (newest wins), so updates never pile up however slowly the
 *       client reads — and their payloads are shared by all clients, not copied;
 *   <li>replies and errors (owned bytes) may total at most {@code maxOwnedBytes}; one more and
 *       {@link #offer} refuses, and the server drops the client as too slow.
 * </ul>
 *
 * <p>Thread-safe: workers, the publisher and the robot's cycle add; the I/O thread takes.
 */
final class OutboundQueue {

  @GuardedBy("this")
  private final ArrayDeque<Outgoing> queue = new ArrayDeque<>();

  @GuardedBy("this")
  private final Map<Integer, Outgoing> pendingUpdates = new HashMap<>();

  private final long maxOwnedBytes;

  @GuardedBy("this")
  private long ownedBytes;

  @GuardedBy("this")
  private long sharedBytes;

  @GuardedBy("this")
  private long peakBytes;

  @GuardedBy("this")
  private long coalesced;

  OutboundQueue(long maxOwnedBytes) {
    this.maxOwnedBytes = maxOwnedBytes;
  }

  /**
   * Adds a reply or control frame.
   *
   * @return false if it would take the client's owned bytes over the limit (nothing is added); a
   *     single item larger than the limit is accepted when nothing else is waiting
   */
  synchronized boolean offer(Outgoing o) {
    long size = o.size();
    if (o.owned) {
      if (ownedBytes > 0 && ownedBytes + size > maxOwnedBytes) {
        return false;
      }
      ownedBytes += size;
    } else {
      sharedBytes += size;
    }
    queue.add(o);
    peak();
    return true;
  }

  /** Adds an update, replacing the subscription's waiting update if there is one. */
  synchronized void offerUpdate(Outgoing o) {
    Outgoing waiting = pendingUpdates.get(o.coalesceKey);
    if (waiting != null && !waiting.started) {
      sharedBytes += o.size() - waiting.size();
      waiting.replaceUpdate(o.payload, o.version);
      coalesced++;
      return;
    }
    sharedBytes += o.size();
    queue.add(o);
    pendingUpdates.put(o.coalesceKey, o);
    peak();
  }

  @GuardedBy("this")
  private void peak() {
    peakBytes = Math.max(peakBytes, ownedBytes + sharedBytes);
  }

  /** Takes the next item to write (it stays counted until {@link #finished}); null if none. */
  synchronized Outgoing start() {
    Outgoing o = queue.poll();
    if (o != null) {
      o.started = true;
      if (o.coalesceKey >= 0 && pendingUpdates.get(o.coalesceKey) == o) {
        pendingUpdates.remove(o.coalesceKey);
      }
    }
    return o;
  }

  /** The item has been written completely. */
  synchronized void finished(Outgoing o) {
    if (o.owned) {
      ownedBytes -= o.size();
    } else {
      sharedBytes -= o.size();
    }
  }

  /** Whether nothing waits. */
  synchronized boolean isEmpty() {
    return queue.isEmpty();
  }

  /** Bytes waiting or being written, owned and shared. */
  synchronized long queuedBytes() {
    return ownedBytes + sharedBytes;
  }

  /** Reply bytes waiting or being written. */
  synchronized long ownedBytes() {
    return ownedBytes;
  }

  /** Most bytes ever waiting at once. */
  synchronized long peakBytes() {
    return peakBytes;
  }

  /** Updates replaced by newer ones before they were sent. */
  synchronized long coalescedCount() {
    return coalesced;
  }

  /** Forgets everything (the client is gone). */
  synchronized void clear() {
    queue.clear();
    pendingUpdates.clear();
    ownedBytes = 0;
    sharedBytes = 0;
  }
}
