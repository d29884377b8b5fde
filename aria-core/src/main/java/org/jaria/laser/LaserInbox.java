package org.jaria.laser;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Predicate;
import org.jaria.connection.ArDeviceConnection;

/**
 * What a laser driver has read from its port, cut into answers by the laser's own framer (LMS
 * telegrams, SCIP blocks) and kept until the driver takes them: the one read-and-wait loop both
 * drivers use, so a timeout or a closed port means the same for each.
 *
 * <p>Used only by the driver's reader thread (or by the connecting thread before that starts).
 *
 * @param <T> one answer of the laser
 */
final class LaserInbox<T> {

  /** Cuts bytes into answers: the laser's receiver. */
  interface Framer<T> {
    void feed(byte[] b, int off, int len, Consumer<T> out);
  }

  private final Framer<T> framer;
  private final byte[] buf;
  private final Deque<T> inbox = new ArrayDeque<>();
  // bound once: a method reference per read would allocate on the scan path
  private final Consumer<T> add = inbox::add;

  LaserInbox(Framer<T> framer, int bufferSize) {
    this.framer = framer;
    this.buf = new byte[bufferSize];
  }

  /** Forgets answers not yet taken (a new connection starts clean). */
  void clear() {
    inbox.clear();
  }

  /**
   * Waits for the answer {@code wanted} accepts, reading the port until {@code timeoutMs} of the
   * connection's clock has passed; answers in between are dropped.
   *
   * @return the answer, or null on a timeout or an answer {@code refused} matches
   */
  T await(ArDeviceConnection c, long timeoutMs, Predicate<T> wanted, Predicate<T> refused)
      throws IOException, InterruptedException {
    long deadline = c.clock().nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
    while (true) {
      while (!inbox.isEmpty()) {
        T t = inbox.poll();
        if (wanted.test(t)) {
          return t;
        }
        if (refused.test(t)) {
          return null;
        }
      }
      long left = TimeUnit.NANOSECONDS.toMillis(deadline - c.clock().nanoTime());
      if (left <= 0) {
        return null;
      }
      if (Thread.interrupted()) {
        throw new InterruptedException();
      }
      read(c, Math.min(left, 100));
    }
  }

  /** Reads what arrives within {@code waitMs} and hands every answer to {@code each}. */
  void drain(ArDeviceConnection c, long waitMs, Consumer<T> each) throws IOException {
    read(c, waitMs);
    while (!inbox.isEmpty()) {
      each.accept(inbox.poll());
    }
  }

  private void read(ArDeviceConnection c, long waitMs) throws IOException {
    int n = c.read(buf, 0, buf.length, waitMs);
    if (n < 0) {
      throw new IOException("the connection closed");
    }
    framer.feed(buf, 0, n, add);
  }
}
