package org.jaria.connection;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.clock.Clock;

/**
 * One end of an in-memory byte pipe: what a test or the simulator's lockstep mode uses instead of a
 * socket. Bytes written to one end are read from the other; reads wait on the pipe's {@link Clock},
 * so on a {@link org.jaria.clock.VirtualClock} a read timeout passes only when virtual time does.
 *
 * <p>Writes never block (a lockstep driver writes and reads both ends from one thread); a reader
 * that falls more than {@link #MAX_BUFFERED} bytes behind makes the writer fail instead of letting
 * memory grow without bound.
 */
public final class PipeConnection implements ArDeviceConnection {

  /** Most unread bytes one direction may hold. */
  public static final int MAX_BUFFERED = 16 << 20;

  /** The two ends of a pipe. */
  public record Pair(PipeConnection a, PipeConnection b) {}

  /** One direction of the pipe: a growable ring of bytes. */
  private static final class Channel {
    final ReentrantLock lock = new ReentrantLock();
    final Condition readable = lock.newCondition();

    @GuardedBy("lock")
    byte[] data = new byte[4096];

    @GuardedBy("lock")
    int head;

    @GuardedBy("lock")
    int size;

    @GuardedBy("lock")
    boolean closed;
  }

  private final String name;
  private final Clock clock;
  private final Channel in;
  private final Channel out;
  private PipeConnection peer;
  private volatile Status status = Status.NEVER_OPENED;
  private volatile long timeRead;

  private PipeConnection(String name, Clock clock, Channel in, Channel out) {
    this.name = name;
    this.clock = clock;
    this.in = in;
    this.out = out;
  }

  /** A new pipe; both ends start unopened (call {@link #open()} on each, or use them opened). */
  public static Pair pair(Clock clock) {
    return pair(clock, "pipe");
  }

  /** A new pipe whose ends are named {@code name}.a and {@code name}.b in messages. */
  public static Pair pair(Clock clock, String name) {
    Channel ab = new Channel();
    Channel ba = new Channel();
    PipeConnection a = new PipeConnection(name + ".a", clock, ba, ab);
    PipeConnection b = new PipeConnection(name + ".b", clock, ab, ba);
    a.peer = b;
    b.peer = a;
    return new Pair(a, b);
  }

  /** The other end. */
  public PipeConnection peer() {
    return peer;
  }

  @Override
  public void open() throws IOException {
    if (status == Status.NEVER_OPENED) {
      status = Status.OPEN;
    } else if (status != Status.OPEN) {
      throw new IOException(name + " was closed; a pipe cannot be reopened, make a new pair");
    }
  }

  @Override
  public Status getStatus() {
    return status;
  }

  @Override
  public String getOpenMessage() {
    return "";
  }

  @Override
  public int read(byte[] buf, int off, int len, long timeoutMs) throws IOException {
    if (status != Status.OPEN) {
      throw new IOException(name + " is not open (status " + status + ")");
    }
    Channel c = in;
    c.lock.lock();
    try {
      if (c.size == 0 && !c.closed && timeoutMs > 0) {
        long deadline = clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (c.size == 0 && !c.closed && status == Status.OPEN) {
          try {
            if (!clock.awaitUntil(c.lock, c.readable, deadline)) {
              break;
            }
          } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException(name + ": interrupted while reading", e);
          }
        }
      }
      if (c.size == 0) {
        if (c.closed) {
          if (status == Status.OPEN) {
            status = Status.CLOSED_ERROR;
          }
          return -1;
        }
        return 0;
      }
      int n = Math.min(len, c.size);
      int first = Math.min(n, c.data.length - c.head);
      System.arraycopy(c.data, c.head, buf, off, first);
      System.arraycopy(c.data, 0, buf, off + first, n - first);
      c.head = (c.head + n) % c.data.length;
      c.size -= n;
      timeRead = clock.nanoTime();
      return n;
    } finally {
      c.lock.unlock();
    }
  }

  /** Bytes waiting to be read at this end. */
  public int available() {
    in.lock.lock();
    try {
      return in.size;
    } finally {
      in.lock.unlock();
    }
  }

  @Override
  public void write(byte[] buf, int off, int len) throws IOException {
    if (status != Status.OPEN) {
      throw new IOException(name + " is not open (status " + status + ")");
    }
    Channel c = out;
    c.lock.lock();
    try {
      if (c.closed) {
        status = Status.CLOSED_ERROR;
        throw new IOException(name + ": the other end closed the pipe");
      }
      if (c.size + len > MAX_BUFFERED) {
        throw new IOException(name + ": the reader is " + c.size + " bytes behind; giving up");
      }
      if (c.size + len > c.data.length) {
        grow(c, c.size + len);
      }
      int tail = (c.head + c.size) % c.data.length;
      int first = Math.min(len, c.data.length - tail);
      System.arraycopy(buf, off, c.data, tail, first);
      System.arraycopy(buf, off + first, c.data, 0, len - first);
      c.size += len;
      c.readable.signalAll();
    } finally {
      c.lock.unlock();
    }
  }

  @GuardedBy("c.lock")
  private static void grow(Channel c, int need) {
    int cap = c.data.length;
    while (cap < need) {
      cap *= 2;
    }
    byte[] bigger = new byte[cap];
    int first = Math.min(c.size, c.data.length - c.head);
    System.arraycopy(c.data, c.head, bigger, 0, first);
    System.arraycopy(c.data, 0, bigger, first, c.size - first);
    c.data = bigger;
    c.head = 0;
  }

  @Override
  public void close() {
    if (status == Status.OPEN || status == Status.NEVER_OPENED) {
      status = Status.CLOSED_NORMALLY;
    }
    shut(out);
    shut(in);
  }

  /**
   * Simulates a cable pulled out: both ends fail, the other end's reads return end-of-stream and
   * this end's status becomes {@link Status#CLOSED_ERROR}.
   */
  public void breakConnection() {
    status = Status.CLOSED_ERROR;
    shut(out);
    shut(in);
  }

  private static void shut(Channel c) {
    c.lock.lock();
    try {
      c.closed = true;
      c.readable.signalAll();
    } finally {
      c.lock.unlock();
    }
  }

  @Override
  public long getTimeRead() {
    return timeRead;
  }

  @Override
  public Clock clock() {
    return clock;
  }

  @Override
  public String getPortName() {
    return name;
  }

  @Override
  public String toString() {
    return name + " (" + status + ")";
  }
}
