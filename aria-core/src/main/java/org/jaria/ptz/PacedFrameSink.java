package org.jaria.ptz;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Iterator;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.jaria.clock.Clock;

/**
 * Spaces a serial camera's command frames out in time. A VC-C4 ignores a command that arrives while
 * it is still busy with the previous one, and without its answers (ARIA's one-way mode) the only
 * safe rule is ARIA's: at least 300 ms between frames. Frames that come sooner wait in a queue; a
 * newer position or zoom request replaces a queued one of the same command, because only the latest
 * target matters (a program that nudges the tilt every 100 ms cycle must not build a backlog).
 * {@link #flush()} sends what is due; call it often (each robot cycle).
 *
 * <p>Thread-safe.
 */
public final class PacedFrameSink implements Consumer<byte[]> {

  /** ARIA's wait between frames when the camera does not answer, ms. */
  public static final long DEFAULT_INTERVAL_MS = 300;

  /** Commands whose newest frame makes older queued ones pointless. */
  private static final int[] SUPERSEDING = {
    VCC4Packets.PAN_TILT, VCC4Packets.ZOOM, VCC4Packets.PAN_SLEW, VCC4Packets.TILT_SLEW
  };

  private final Consumer<byte[]> out;
  private final Clock clock;
  private final long intervalNanos;
  private final Deque<byte[]> queue = new ArrayDeque<>();
  private long lastSentNanos;
  private boolean sentAny;
  private long superseded;

  /** Frames to {@code out}, at most one per {@code intervalMs} of {@code clock}'s time. */
  public PacedFrameSink(Consumer<byte[]> out, Clock clock, long intervalMs) {
    if (out == null || clock == null) {
      throw new IllegalArgumentException("a paced sink needs a sink and a clock");
    }
    this.out = out;
    this.clock = clock;
    this.intervalNanos = TimeUnit.MILLISECONDS.toNanos(Math.max(0, intervalMs));
  }

  /** Queues a frame, sending it at once if the line has been quiet long enough. */
  @Override
  public synchronized void accept(byte[] frame) {
    int cmd = command(frame);
    if (isSuperseding(cmd)) {
      for (Iterator<byte[]> it = queue.iterator(); it.hasNext(); ) {
        if (command(it.next()) == cmd) {
          it.remove();
          superseded++;
        }
      }
    }
    queue.addLast(frame.clone());
    flush();
  }

  /** Sends the next queued frame if it is due. */
  public synchronized void flush() {
    long now = clock.nanoTime();
    if (!queue.isEmpty() && (!sentAny || now - lastSentNanos >= intervalNanos)) {
      out.accept(queue.removeFirst());
      lastSentNanos = now;
      sentAny = true;
    }
  }

  /** Frames waiting to be sent. */
  public synchronized int pending() {
    return queue.size();
  }

  /** Frames dropped because a newer one of the same command replaced them. */
  public synchronized long supersededCount() {
    return superseded;
  }

  private static int command(byte[] frame) {
    return frame.length > 4 ? frame[4] & 0xFF : -1;
  }

  private static boolean isSuperseding(int cmd) {
    for (int c : SUPERSEDING) {
      if (c == cmd) {
        return true;
      }
    }
    return false;
  }
}
