package org.jaria.connection;

import java.io.IOException;
import org.jaria.clock.Clock;

/**
 * A byte pipe to a robot or another device: a TCP socket, a serial port, or an in-memory pipe in
 * tests (ARIA's {@code ArDeviceConnection}).
 *
 * <p>Reading and writing may happen on different threads at the same time; two threads must not
 * read (or write) at once. {@link #close()} may be called from any thread and wakes a blocked
 * reader.
 */
public interface ArDeviceConnection extends AutoCloseable {

  /** Where a connection is in its life. */
  enum Status {
    /** Created, not yet opened. */
    NEVER_OPENED,
    /** Open and usable. */
    OPEN,
    /** The last open attempt failed; see {@link #getOpenMessage()}. */
    OPEN_FAILED,
    /** Closed by {@link #close()}. */
    CLOSED_NORMALLY,
    /** Closed because of an error (peer vanished, device unplugged). */
    CLOSED_ERROR
  }

  /**
   * Opens the connection.
   *
   * @throws IOException with a message that says what failed and what to try; the same text is then
   *     available from {@link #getOpenMessage()}
   */
  void open() throws IOException;

  /** ARIA's {@code openSimple}: opens and returns whether it worked, instead of throwing. */
  default boolean openSimple() {
    try {
      open();
      return true;
    } catch (IOException e) {
      return false;
    }
  }

  /** The current status. */
  Status getStatus();

  /** Why the last {@link #open()} failed, or an empty string. */
  String getOpenMessage();

  /**
   * Reads up to {@code len} bytes, waiting at most {@code timeoutMs} for the first one (0 means
   * only take what has already arrived).
   *
   * @return the number of bytes read, 0 if none arrived in time, or -1 if the other end closed
   * @throws IOException if the connection failed or is not open
   */
  int read(byte[] buf, int off, int len, long timeoutMs) throws IOException;

  /**
   * Writes all {@code len} bytes.
   *
   * @throws IOException if the connection failed or is not open
   */
  void write(byte[] buf, int off, int len) throws IOException;

  /** Closes the connection; idempotent. */
  @Override
  void close();

  /** The time, on {@link #clock()}, of the last read that returned data (0 if none yet). */
  long getTimeRead();

  /** The clock this connection times its reads with. */
  Clock clock();

  /** A human-readable description, e.g. {@code tcp localhost:8101} or {@code serial /dev/ttyS0}. */
  String getPortName();
}
