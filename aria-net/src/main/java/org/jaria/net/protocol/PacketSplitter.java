package org.jaria.net.protocol;

import java.nio.ByteBuffer;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * Cuts a TCP byte stream into ArNetworking packets: bytes are read into {@link #buffer()} as they
 * arrive, in pieces of any size, and {@link #drain} hands every complete packet (sync bytes, length
 * and checksum checked) to a sink. The buffer never grows past ArNetworking's largest packet (32000
 * bytes), so a peer cannot make the reader allocate without bound.
 *
 * <p>ARIA's own receiver skips a bad byte or a bad checksum and looks for the next packet; we close
 * the connection instead ({@link ProtocolException}): a stream with a broken packet cannot be
 * trusted, and a real ARIA peer never sends one.
 *
 * <p>Not thread-safe: one splitter per connection, used by the thread that reads it.
 */
public final class PacketSplitter {

  /** Receives one packet. */
  @FunctionalInterface
  public interface Sink {
    /** Handles one packet. */
    void packet(ArNetPacket p) throws ProtocolException;
  }

  private final ByteBuffer buf = ByteBuffer.allocate(ArNetPacket.MAX_LENGTH);
  private long packets;

  /** Where to put bytes read from the connection (write mode; it has room for at least one). */
  public ByteBuffer buffer() {
    return buf;
  }

  /** Bytes held: a packet not complete yet. */
  public int pendingBytes() {
    return buf.position();
  }

  /** Packets handed to sinks so far. */
  public long packetCount() {
    return packets;
  }

  /**
   * Hands every complete packet in the buffer to {@code sink}, in order, and keeps the rest.
   *
   * @throws ProtocolException if the stream does not start with the sync bytes, a length is out of
   *     range or a checksum is wrong, or if the sink throws one (the connection should then be
   *     closed)
   */
  public void drain(Sink sink) throws ProtocolException {
    buf.flip();
    try {
      while (buf.remaining() >= 4) {
        int p = buf.position();
        byte[] a = buf.array();
        if ((a[p] & 0xFF) != ArNetPacket.SYNC1 || (a[p + 1] & 0xFF) != ArNetPacket.SYNC2) {
          throw new ProtocolException(
              NetError.MALFORMED,
              String.format(
                  "not an ArNetworking packet: it starts with %02x %02x, not 0f 0c",
                  a[p] & 0xFF, a[p + 1] & 0xFF));
        }
        int len = (a[p + 2] & 0xFF) | (a[p + 3] & 0xFF) << 8;
        if (len < ArNetPacket.HEADER_LENGTH + ArNetPacket.FOOTER_LENGTH
            || len > ArNetPacket.MAX_LENGTH) {
          throw new ProtocolException(
              NetError.MALFORMED,
              "a packet announced " + len + " bytes; ArNetworking packets are 8.." + 32000);
        }
        if (buf.remaining() < len) {
          break;
        }
        ArNetPacket packet;
        try {
          packet = ArNetPacket.fromWire(a, p, len);
        } catch (ArNetPacketException e) {
          throw new ProtocolException(NetError.MALFORMED, e.getMessage(), e);
        }
        buf.position(p + len);
        packets++;
        sink.packet(packet);
      }
    } finally {
      buf.compact();
    }
  }
}
