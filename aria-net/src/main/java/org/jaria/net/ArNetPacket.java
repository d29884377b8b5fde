package org.jaria.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessageFormat;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessagePackException;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.ValueType;

/**
 * The body of a network message: a sequence of typed values (ARIA's {@code ArNetPacket}). A handler
 * reads the request's arguments in order with the {@code bufTo...} methods and writes its reply
 * with the {@code ...ToBuf} methods, exactly as in ArNetworking:
 *
 * <pre>{@code
 * server.addData("gotoPose", "drives to a pose", "double x, double y, double th", "none",
 *     "Movement", Where.CYCLE,
 *     (client, request, reply) -> {
 *       double x = request.bufToDouble();
 *       double y = request.bufToDouble();
 *       ...
 *       reply.strToBuf("going");
 *     });
 * }</pre>
 *
 * <p>Unlike ARIA's fixed-width packets, every value carries its type (the encoding is <a
 * href="https://msgpack.org">MessagePack</a>, see {@code PROTOCOL.md}): a reader that asks for a
 * string where the sender put a number gets a clear {@link ArNetPacketException} instead of
 * garbage, integers take as few bytes as their value needs, and programs in other languages can
 * read the packets with any MessagePack library.
 *
 * <p>Reading is defensive: lengths and counts are checked against the bytes actually present before
 * anything is allocated, and nesting is limited, so a hostile packet cannot make the reader
 * allocate or recurse without bound. A packet is not thread-safe; it belongs to the code that
 * received or built it.
 */
public final class ArNetPacket {

  /** Deepest nesting of arrays and maps {@link #bufToValue()} accepts. */
  public static final int MAX_DEPTH = 16;

  private static final MessagePack.UnpackerConfig UNPACKER = new MessagePack.UnpackerConfig();

  /** Most packets are small: start with a small buffer (it grows as needed). */
  private static final MessagePack.PackerConfig PACKER =
      new MessagePack.PackerConfig().withBufferSize(512);

  private final MessageBufferPacker packer;
  private byte[] data;
  private int offset;
  private int length;
  private MessageUnpacker unpacker;
  private int valuesRead;

  /** An empty packet to write values into. */
  public ArNetPacket() {
    packer = PACKER.newBufferPacker();
  }

  private ArNetPacket(byte[] data, int offset, int length) {
    this.packer = null;
    this.data = data;
    this.offset = offset;
    this.length = length;
    resetRead();
  }

  /** A packet that reads the encoded values in {@code data} (not copied: do not change it). */
  public static ArNetPacket wrap(byte[] data) {
    return wrap(data, 0, data.length);
  }

  /** A packet that reads {@code length} encoded bytes of {@code data} from {@code offset}. */
  public static ArNetPacket wrap(byte[] data, int offset, int length) {
    if (offset < 0 || length < 0 || offset + length > data.length) {
      throw new IndexOutOfBoundsException(
          "slice " + offset + "+" + length + " outside an array of " + data.length);
    }
    return new ArNetPacket(data, offset, length);
  }

  /**
   * A packet holding {@code values}, each written with {@link #valueToBuf(Object)}: a quick way to
   * build arguments, {@code ArNetPacket.of(1000.0, 0.0, 90.0)}.
   */
  public static ArNetPacket of(Object... values) {
    ArNetPacket p = new ArNetPacket();
    for (Object v : values) {
      p.valueToBuf(v);
    }
    return p;
  }

  // ------------------------------------------------------------------ writing

  private MessageBufferPacker out() {
    if (packer == null) {
      throw new IllegalStateException(
          "this packet was received (or wrapped) for reading; build a new ArNetPacket to write");
    }
    return packer;
  }

  /** Appends an integer. */
  public ArNetPacket intToBuf(long value) {
    try {
      out().packLong(value);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Appends a floating-point number. */
  public ArNetPacket doubleToBuf(double value) {
    try {
      out().packDouble(value);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Appends a string (null is written as nil). */
  public ArNetPacket strToBuf(String value) {
    try {
      if (value == null) {
        out().packNil();
      } else {
        out().packString(value);
      }
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Appends a boolean. */
  public ArNetPacket boolToBuf(boolean value) {
    try {
      out().packBoolean(value);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Appends nil (an absent value). */
  public ArNetPacket nilToBuf() {
    try {
      out().packNil();
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Appends a block of bytes (an image, a file). */
  public ArNetPacket dataToBuf(byte[] bytes) {
    return dataToBuf(bytes, 0, bytes.length);
  }

  /** Appends {@code len} bytes of {@code bytes} from {@code off}. */
  public ArNetPacket dataToBuf(byte[] bytes, int off, int len) {
    try {
      out().packBinaryHeader(len);
      out().writePayload(bytes, off, len);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /**
   * Starts an array of {@code count} values: the next {@code count} values written are its elements
   * (each may itself be an array).
   */
  public ArNetPacket arrayToBuf(int count) {
    try {
      out().packArrayHeader(count);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Starts a map of {@code count} entries: then write key, value, key, value ... */
  public ArNetPacket mapToBuf(int count) {
    try {
      out().packMapHeader(count);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** Appends the first {@code n} numbers of {@code values} as one array of integers. */
  public ArNetPacket intsToBuf(int[] values, int n) {
    arrayToBuf(n);
    try {
      for (int i = 0; i < n; i++) {
        out().packInt(values[i]);
      }
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /**
   * Appends a value of a simple type: null, Boolean, any integer type, Float or Double, String,
   * byte[], or a List/Collection or Map of those.
   *
   * @throws IllegalArgumentException for any other type
   */
  public ArNetPacket valueToBuf(Object v) {
    if (v == null) {
      return nilToBuf();
    } else if (v instanceof Boolean b) {
      return boolToBuf(b);
    } else if (v instanceof Byte
        || v instanceof Short
        || v instanceof Integer
        || v instanceof Long) {
      return intToBuf(((Number) v).longValue());
    } else if (v instanceof Float || v instanceof Double) {
      return doubleToBuf(((Number) v).doubleValue());
    } else if (v instanceof String s) {
      return strToBuf(s);
    } else if (v instanceof byte[] b) {
      return dataToBuf(b);
    } else if (v instanceof Collection<?> c) {
      arrayToBuf(c.size());
      for (Object e : c) {
        valueToBuf(e);
      }
      return this;
    } else if (v instanceof Map<?, ?> m) {
      mapToBuf(m.size());
      for (Map.Entry<?, ?> e : m.entrySet()) {
        valueToBuf(e.getKey());
        valueToBuf(e.getValue());
      }
      return this;
    }
    throw new IllegalArgumentException(
        "cannot put a "
            + v.getClass().getName()
            + " in a packet: use numbers, strings, booleans,"
            + " byte arrays, lists or maps of them");
  }

  /** Appends encoded values taken verbatim from another packet's {@link #toByteArray()}. */
  public ArNetPacket encodedToBuf(byte[] encoded) {
    try {
      out().writePayload(encoded);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
    return this;
  }

  /** The encoded values: what was written, or what is being read (a copy). */
  public byte[] toByteArray() {
    if (packer != null) {
      return packer.toByteArray();
    }
    return Arrays.copyOfRange(data, offset, offset + length);
  }

  /** Number of encoded bytes. */
  public int getLength() {
    return packer != null ? (int) packer.getTotalWrittenBytes() : length;
  }

  /** A new packet that reads what has been written into this one. */
  public ArNetPacket toReader() {
    byte[] b = toByteArray();
    return new ArNetPacket(b, 0, b.length);
  }

  // ------------------------------------------------------------------ reading

  private MessageUnpacker in() {
    if (unpacker == null) {
      throw new IllegalStateException(
          "this packet is being built; call toReader() to read what was written");
    }
    return unpacker;
  }

  /** Starts reading again from the first value. */
  public void resetRead() {
    if (data == null) {
      throw new IllegalStateException("a packet being built has nothing to read yet");
    }
    unpacker = UNPACKER.newUnpacker(data, offset, length);
    valuesRead = 0;
  }

  /** Bytes not read yet. */
  public int getRemaining() {
    return length - (int) in().getTotalReadBytes();
  }

  /** Bytes read so far. */
  public int getReadLength() {
    return (int) in().getTotalReadBytes();
  }

  /** Whether another value follows. */
  public boolean hasMore() {
    return getRemaining() > 0;
  }

  private ValueType next(String wanted) {
    if (!hasMore()) {
      throw new ArNetPacketException(
          "expected " + wanted + " as value " + (valuesRead + 1) + " but the packet ended");
    }
    try {
      MessageFormat f = in().getNextFormat();
      if (f == MessageFormat.NEVER_USED) {
        throw new ArNetPacketException(
            "value " + (valuesRead + 1) + " starts with a reserved byte (0xc1): not MessagePack");
      }
      return f.getValueType();
    } catch (IOException | MessagePackException e) {
      throw new ArNetPacketException("value " + (valuesRead + 1) + " is cut short", e);
    }
  }

  private ArNetPacketException wrongType(String wanted, ValueType got) {
    return new ArNetPacketException(
        "expected "
            + wanted
            + " as value "
            + (valuesRead + 1)
            + " but found "
            + got.name().toLowerCase(java.util.Locale.ROOT));
  }

  private ArNetPacketException broken(Exception e) {
    return new ArNetPacketException(
        "value " + (valuesRead + 1) + " is malformed: " + e.getMessage(), e);
  }

  /** Reads an integer that fits an int. */
  public int bufToInt() {
    long v = bufToLong();
    if (v < Integer.MIN_VALUE || v > Integer.MAX_VALUE) {
      throw new ArNetPacketException(
          "value " + valuesRead + " is " + v + ", too large for a 32-bit integer");
    }
    return (int) v;
  }

  /** Reads an integer. */
  public long bufToLong() {
    ValueType t = next("an integer");
    if (t != ValueType.INTEGER) {
      throw wrongType("an integer", t);
    }
    try {
      long v = in().unpackLong();
      valuesRead++;
      return v;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Reads a number (an integer is accepted too). */
  public double bufToDouble() {
    ValueType t = next("a number");
    try {
      double v;
      if (t == ValueType.FLOAT) {
        v = in().unpackDouble();
      } else if (t == ValueType.INTEGER) {
        v = in().unpackLong();
      } else {
        throw wrongType("a number", t);
      }
      valuesRead++;
      return v;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Reads a string (nil reads as null). */
  public String bufToStr() {
    ValueType t = next("a string");
    try {
      if (t == ValueType.NIL) {
        in().unpackNil();
        valuesRead++;
        return null;
      }
      if (t != ValueType.STRING) {
        throw wrongType("a string", t);
      }
      int len = in().unpackRawStringHeader();
      checkLength(len, "string");
      byte[] b = in().readPayload(len);
      valuesRead++;
      return new String(b, java.nio.charset.StandardCharsets.UTF_8);
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Reads a boolean. */
  public boolean bufToBool() {
    ValueType t = next("a boolean");
    if (t != ValueType.BOOLEAN) {
      throw wrongType("a boolean", t);
    }
    try {
      boolean v = in().unpackBoolean();
      valuesRead++;
      return v;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Whether the next value is nil; if so it is consumed. */
  public boolean bufToNil() {
    if (!hasMore()) {
      return false;
    }
    try {
      if (in().tryUnpackNil()) {
        valuesRead++;
        return true;
      }
      return false;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Reads a block of bytes. */
  public byte[] bufToData() {
    ValueType t = next("bytes");
    if (t != ValueType.BINARY) {
      throw wrongType("bytes", t);
    }
    try {
      int len = in().unpackBinaryHeader();
      checkLength(len, "byte block");
      byte[] b = in().readPayload(len);
      valuesRead++;
      return b;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /**
   * Reads the start of an array and returns its element count; the elements are the next values.
   */
  public int bufToArray() {
    ValueType t = next("an array");
    if (t != ValueType.ARRAY) {
      throw wrongType("an array", t);
    }
    try {
      int n = in().unpackArrayHeader();
      // Every element takes at least one byte: a larger count is a lie.
      checkLength(n, "array");
      valuesRead++;
      return n;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Reads the start of a map and returns its entry count; then read key, value, key, value ... */
  public int bufToMap() {
    ValueType t = next("a map");
    if (t != ValueType.MAP) {
      throw wrongType("a map", t);
    }
    try {
      int n = in().unpackMapHeader();
      checkLength(n, "map");
      valuesRead++;
      return n;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /** Reads an array of integers (as written by {@link #intsToBuf}). */
  public int[] bufToInts() {
    int n = bufToArray();
    int[] v = new int[n];
    for (int i = 0; i < n; i++) {
      v[i] = bufToInt();
    }
    return v;
  }

  /** Skips the next value (with everything nested in it). */
  public void skip() {
    next("a value");
    try {
      in().skipValue();
      valuesRead++;
    } catch (IOException | MessagePackException e) {
      throw broken(e);
    }
  }

  /**
   * Reads the next value as a plain Java object: null, Boolean, Long, Double, String, byte[], List
   * or Map (nesting at most {@link #MAX_DEPTH} deep).
   */
  public Object bufToValue() {
    return readValue(0);
  }

  private Object readValue(int depth) {
    if (depth > MAX_DEPTH) {
      throw new ArNetPacketException("values nested more than " + MAX_DEPTH + " deep");
    }
    ValueType t = next("a value");
    switch (t) {
      case NIL -> {
        bufToNil();
        return null;
      }
      case BOOLEAN -> {
        return bufToBool();
      }
      case INTEGER -> {
        return bufToLong();
      }
      case FLOAT -> {
        return bufToDouble();
      }
      case STRING -> {
        return bufToStr();
      }
      case BINARY -> {
        return bufToData();
      }
      case ARRAY -> {
        int n = bufToArray();
        List<Object> list = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
          list.add(readValue(depth + 1));
        }
        return list;
      }
      case MAP -> {
        int n = bufToMap();
        Map<Object, Object> map = new LinkedHashMap<>();
        for (int i = 0; i < n; i++) {
          Object k = readValue(depth + 1);
          map.put(k, readValue(depth + 1));
        }
        return map;
      }
      case EXTENSION -> {
        skip();
        return null;
      }
    }
    throw new ArNetPacketException("unknown value type " + t);
  }

  private void checkLength(long len, String what) {
    if (len < 0 || len > getRemaining()) {
      throw new ArNetPacketException(
          "a "
              + what
              + " of "
              + len
              + " claimed as value "
              + (valuesRead + 1)
              + " but only "
              + getRemaining()
              + " bytes are left");
    }
  }

  /**
   * Checks that the rest of the packet is a well-formed sequence of values, without building them;
   * the read position is restored afterwards.
   *
   * @throws ArNetPacketException naming the first bad value
   */
  public void validate() {
    MessageUnpacker saved = unpacker;
    int savedCount = valuesRead;
    long start = in().getTotalReadBytes();
    unpacker = UNPACKER.newUnpacker(data, offset + (int) start, length - (int) start);
    int savedOffset = offset;
    int savedLength = length;
    offset += (int) start;
    length -= (int) start;
    try {
      while (hasMore()) {
        skip();
      }
    } finally {
      offset = savedOffset;
      length = savedLength;
      unpacker = saved;
      valuesRead = savedCount;
    }
  }

  /** The values, decoded, for logs and test messages. */
  @Override
  public String toString() {
    ArNetPacket r = packer != null ? toReader() : wrap(data, offset, length);
    List<Object> values = new ArrayList<>();
    try {
      while (r.hasMore()) {
        Object v = r.bufToValue();
        values.add(v instanceof byte[] b ? "<" + b.length + " bytes>" : v);
      }
    } catch (ArNetPacketException e) {
      values.add("<malformed: " + e.getMessage() + ">");
    }
    return "ArNetPacket" + values;
  }
}
