package org.jaria.net.protocol;

import java.nio.ByteBuffer;
import org.jaria.net.ArNetPacket;

/**
 * Building and splitting frames: a 4-byte big-endian length, then that many bytes of MessagePack
 * values, the first being the {@link Kind}. Also a tiny allocation-free MessagePack writer for the
 * few integers and booleans of a frame header, used on the server's I/O thread.
 */
public final class Frames {

  private Frames() {}

  /** Largest header {@link #putHeader} writes: length, kind, two 9-byte integers, a boolean. */
  public static final int MAX_HEADER_BYTES = Protocol.LENGTH_BYTES + 1 + 2 * 9 + 1;

  /** A complete frame: length prefix, kind, then the values written in {@code body}. */
  public static byte[] frame(Kind kind, ArNetPacket body) {
    byte[] b = body.toByteArray();
    int kindBytes = intSize(kind.code());
    ByteBuffer out = ByteBuffer.allocate(Protocol.LENGTH_BYTES + kindBytes + b.length);
    out.putInt(kindBytes + b.length);
    putInt(out, kind.code());
    out.put(b);
    return out.array();
  }

  /** A complete frame of {@code kind} holding {@code values} (see {@link ArNetPacket#of}). */
  public static byte[] frame(Kind kind, Object... values) {
    return frame(kind, ArNetPacket.of(values));
  }

  /**
   * The length announced at the buffer's position (not consumed).
   *
   * @throws ProtocolException if it is 0 or more than {@code maxFrame}
   */
  public static int peekLength(ByteBuffer buf, int maxFrame) throws ProtocolException {
    int len = buf.getInt(buf.position());
    checkLength(len, maxFrame);
    return len;
  }

  /**
   * Checks an announced frame length.
   *
   * @throws ProtocolException if it is 0, negative or more than {@code maxFrame}
   */
  public static void checkLength(int len, int maxFrame) throws ProtocolException {
    if (len <= 0 || len > maxFrame) {
      throw new ProtocolException(
          NetError.MALFORMED,
          "a frame announced "
              + Integer.toUnsignedString(len)
              + " bytes; frames must be 1.."
              + maxFrame
              + " bytes (is this a JAria client?)");
    }
  }

  /** Bytes MessagePack takes for the integer {@code v}. */
  public static int intSize(long v) {
    if (v >= -32 && v <= 127) {
      return 1;
    } else if (v >= 0) {
      return v <= 0xff ? 2 : v <= 0xffff ? 3 : v <= 0xffffffffL ? 5 : 9;
    } else {
      return v >= Byte.MIN_VALUE ? 2 : v >= Short.MIN_VALUE ? 3 : v >= Integer.MIN_VALUE ? 5 : 9;
    }
  }

  /** Writes the integer {@code v} in MessagePack's shortest form. */
  public static void putInt(ByteBuffer b, long v) {
    if (v >= -32 && v <= 127) {
      b.put((byte) v);
    } else if (v >= 0) {
      if (v <= 0xff) {
        b.put((byte) 0xcc).put((byte) v);
      } else if (v <= 0xffff) {
        b.put((byte) 0xcd).putShort((short) v);
      } else if (v <= 0xffffffffL) {
        b.put((byte) 0xce).putInt((int) v);
      } else {
        b.put((byte) 0xcf).putLong(v);
      }
    } else if (v >= Byte.MIN_VALUE) {
      b.put((byte) 0xd0).put((byte) v);
    } else if (v >= Short.MIN_VALUE) {
      b.put((byte) 0xd1).putShort((short) v);
    } else if (v >= Integer.MIN_VALUE) {
      b.put((byte) 0xd2).putInt((int) v);
    } else {
      b.put((byte) 0xd3).putLong(v);
    }
  }

  /** Writes a MessagePack boolean. */
  public static void putBool(ByteBuffer b, boolean v) {
    b.put((byte) (v ? 0xc3 : 0xc2));
  }

  /**
   * Writes the header of a RESPONSE or UPDATE part into {@code b} (cleared first, flipped after):
   * length prefix (covering header and {@code partBytes}), kind, two integers (request id and data
   * id, or data id and version) and the final flag.
   */
  public static void putHeader(
      ByteBuffer b, Kind kind, long a, long c, boolean last, int partBytes) {
    b.clear();
    int body = intSize(kind.code()) + intSize(a) + intSize(c) + 1 + partBytes;
    b.putInt(body);
    putInt(b, kind.code());
    putInt(b, a);
    putInt(b, c);
    putBool(b, last);
    b.flip();
  }
}
