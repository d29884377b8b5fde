package org.jaria.sim.server;

import java.io.EOFException;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;

/**
 * A simulator's end of a client's TCP connection, non-blocking both ways so that the world thread
 * can serve any number of clients without a thread per client and without ever blocking.
 *
 * <p>Reads take what has arrived (a timeout waits on a selector, but the world always reads with
 * timeout 0). Writes hand the kernel what it accepts at once and keep the rest in a bounded buffer,
 * pushed out by {@link #flush()} on every tick. A client that stops reading until that buffer is
 * full is dropped ({@link IOException} from {@link #write}), so one stuck client cannot stall every
 * other robot or eat memory.
 */
public final class NioSocketConnection implements ArDeviceConnection {

  /** Bytes a client may fall behind before it is dropped (about 10 s of SIPs at full size). */
  public static final int MAX_PENDING_BYTES = 256 * 1024;

  private final SocketChannel channel;
  private final Clock clock;
  private final String name;

  /**
   * Bytes the kernel did not take yet, ready to write (position..limit). Empty until a write is
   * left over, then grown as needed up to {@link #MAX_PENDING_BYTES}: a robot keeps many
   * connections in their handshake, and those must cost next to nothing.
   */
  private ByteBuffer pending = ByteBuffer.allocate(0);

  private final ByteBuffer readWrap = ByteBuffer.allocate(0);
  private Selector readSelector;
  private volatile Status status = Status.OPEN;
  private volatile long timeRead;

  /**
   * Adopts an accepted channel (switched to non-blocking, Nagle off).
   *
   * @throws IOException if the channel cannot be configured
   */
  public NioSocketConnection(SocketChannel channel, Clock clock) throws IOException {
    this.channel = channel;
    this.clock = clock;
    channel.configureBlocking(false);
    channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
    SocketAddress remote = channel.getRemoteAddress();
    this.name =
        "tcp client "
            + (remote instanceof InetSocketAddress a
                ? a.getAddress().getHostAddress() + ":" + a.getPort()
                : String.valueOf(remote));
  }

  @Override
  public void open() throws IOException {
    if (status != Status.OPEN) {
      throw new IOException(name + " is closed; a client connection cannot be reopened");
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
    requireOpen();
    ByteBuffer bb = len == 0 ? readWrap : ByteBuffer.wrap(buf, off, len);
    int n = readSome(bb);
    if (n == 0 && timeoutMs > 0) {
      if (readSelector == null) {
        readSelector = Selector.open();
        channel.register(readSelector, SelectionKey.OP_READ);
      }
      readSelector.select(timeoutMs);
      readSelector.selectedKeys().clear();
      n = readSome(bb);
    }
    return n;
  }

  private int readSome(ByteBuffer bb) throws IOException {
    try {
      int n = channel.read(bb);
      if (n < 0) {
        status = Status.CLOSED_ERROR;
        return -1;
      }
      if (n > 0) {
        timeRead = clock.nanoTime();
      }
      return n;
    } catch (IOException e) {
      fail();
      throw e;
    }
  }

  @Override
  public void write(byte[] buf, int off, int len) throws IOException {
    requireOpen();
    try {
      flush();
      if (!pending.hasRemaining()) {
        ByteBuffer src = ByteBuffer.wrap(buf, off, len);
        channel.write(src);
        off = src.position();
        len = src.remaining();
      }
      if (len > 0) {
        if (pending.remaining() + len > MAX_PENDING_BYTES) {
          fail();
          throw new IOException(
              name
                  + " stopped reading ("
                  + MAX_PENDING_BYTES
                  + " bytes unsent); dropping the client");
        }
        if (pending.capacity() - pending.remaining() < len) {
          int need = pending.remaining() + len;
          ByteBuffer bigger =
              ByteBuffer.allocate(
                  Math.min(MAX_PENDING_BYTES, Math.max(need, 2 * pending.capacity())));
          bigger.put(pending);
          pending = bigger;
        } else {
          pending.compact();
        }
        pending.put(buf, off, len);
        pending.flip();
      }
    } catch (IOException e) {
      fail();
      throw e;
    }
  }

  /**
   * Sends whatever is waiting in the buffer, as far as the kernel accepts it now.
   *
   * @throws IOException if the connection failed
   */
  public void flush() throws IOException {
    if (pending.hasRemaining() && status == Status.OPEN) {
      try {
        channel.write(pending);
      } catch (IOException e) {
        fail();
        throw e;
      }
    }
  }

  /** Bytes written but not yet handed to the kernel. */
  public int pendingBytes() {
    return pending.remaining();
  }

  private void requireOpen() throws IOException {
    if (status != Status.OPEN) {
      if (status == Status.CLOSED_ERROR) {
        throw new EOFException(name + " was closed by the client");
      }
      throw new IOException(name + " is not open (status " + status + ")");
    }
  }

  private void fail() {
    if (status == Status.OPEN) {
      status = Status.CLOSED_ERROR;
    }
    closeQuietly();
  }

  @Override
  public void close() {
    if (status == Status.OPEN) {
      status = Status.CLOSED_NORMALLY;
    }
    closeQuietly();
  }

  private void closeQuietly() {
    try {
      if (readSelector != null) {
        readSelector.close();
      }
    } catch (IOException ignored) {
      // closing anyway
    }
    try {
      channel.close();
    } catch (IOException ignored) {
      // closing anyway
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
