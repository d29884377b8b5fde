package org.jaria.net.protocol;

import java.nio.ByteBuffer;

/**
 * Cuts a byte stream into frames: bytes are read into {@link #buffer()} as they arrive, in pieces
 * of any size, and {@link #drain} hands every complete frame to a sink. The buffer grows for a
 * large frame but never past the largest frame allowed: a length prefix beyond it (or zero) is a
 * {@link ProtocolException} at once, before any byte of it is stored, so a peer cannot make the
 * reader allocate without bound.
 *
 * <p>Not thread-safe: one splitter per connection, used by the thread that reads it.
 */
public final class FrameSplitter {

  /** Receives one frame: {@code len} bytes at {@code off} of {@code a} (valid during the call). */
  @FunctionalInterface
  public interface Sink {
    /** Handles one frame. */
    void frame(byte[] a, int off, int len) throws ProtocolException;
  }

  private final int maxFrame;
  private ByteBuffer buf;

  /**
   * A splitter.
   *
   * @param initialCapacity bytes of the buffer to start with
   * @param maxFrame largest frame body accepted, bytes
   */
  public FrameSplitter(int initialCapacity, int maxFrame) {
    this.maxFrame = maxFrame;
    this.buf = ByteBuffer.allocate(Math.max(Protocol.LENGTH_BYTES, initialCapacity));
  }

  /** Where to put bytes read from the connection (write mode; it has room for at least one). */
  public ByteBuffer buffer() {
    return buf;
  }

  /** Bytes held: a frame not complete yet. */
  public int pendingBytes() {
    return buf.position();
  }

  /** Capacity of the buffer now. */
  public int capacity() {
    return buf.capacity();
  }

  /**
   * Hands every complete frame in the buffer to {@code sink}, in order, and keeps the rest.
   *
   * @throws ProtocolException if a length prefix is zero or larger than the largest frame, or if
   *     the sink throws one (the connection should then be closed: the stream cannot be trusted)
   */
  public void drain(Sink sink) throws ProtocolException {
    buf.flip();
    int need = 0;
    while (buf.remaining() >= Protocol.LENGTH_BYTES) {
      int len = Frames.peekLength(buf, maxFrame);
      if (buf.remaining() < Protocol.LENGTH_BYTES + len) {
        need = Protocol.LENGTH_BYTES + len;
        break;
      }
      int start = buf.position() + Protocol.LENGTH_BYTES;
      buf.position(start + len);
      sink.frame(buf.array(), buf.arrayOffset() + start, len);
    }
    buf.compact();
    if (need > buf.capacity()) {
      ByteBuffer bigger = ByteBuffer.allocate(need);
      buf.flip();
      bigger.put(buf);
      buf = bigger;
    }
  }
}
