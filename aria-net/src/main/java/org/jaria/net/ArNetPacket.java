package org.jaria.net;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;

/**
 * One ArNetworking message (ARIA's {@code ArNetPacket}): a command number and a body of values in
 * ARIA's byte layout. A handler reads the request's arguments in order with the {@code bufTo...}
 * methods and writes its reply with the {@code ...ToBuf} methods, exactly as in ArNetworking:
 *
 * <pre>{@code
 * server.addData("gotoPose", "drives to a pose", "double: x; double: y; double: th", "none",
 *     "Movement", Where.CYCLE,
 *     (client, request, reply) -> {
 *       double x = request.bufToDouble();
 *       ...
 *     });
 * }</pre>
 *
 * <p>The layout is ArNetworking's, so ARIA's C++ programs (and MobileEyes) read what we write:
 * integers are little-endian and fixed-width (1, 2, 4 or 8 bytes), strings end with a zero byte,
 * and a {@code double} travels as its text ({@code %g}, six significant digits, or {@code INF} /
 * {@code -INF}). Nothing carries its type: both sides must agree on the order of the values, which
 * the data's argument and return descriptions state.
 *
 * <p>Reading is strict where ARIA is lenient: a read past the end, a string without its ending zero
 * or a number that is not a number throws {@link ArNetPacketException} instead of returning zero,
 * so a handler never acts on garbage. A packet is not thread-safe; it belongs to the code that
 * received or built it. See {@code aria-net/PROTOCOL.md}.
 */
public final class ArNetPacket {

  /** Largest packet on the wire, header and checksum included (ArNetworking's limit). */
  public static final int MAX_LENGTH = 32000;

  /** Bytes before the body: two sync bytes, the length and the command. */
  public static final int HEADER_LENGTH = 6;

  /** Bytes after the body: the checksum. */
  public static final int FOOTER_LENGTH = 2;

  /** Largest body a packet may carry. */
  public static final int MAX_DATA_LENGTH = MAX_LENGTH - HEADER_LENGTH - FOOTER_LENGTH;

  /** The first sync byte of every packet. */
  public static final int SYNC1 = 0x0F;

  /** The second sync byte of every packet. */
  public static final int SYNC2 = 0x0C;

  private int command;
  private byte[] data;
  private int length;
  private int readPos;
  private final boolean writable;

  /** An empty packet (command 0) to write values into. */
  public ArNetPacket() {
    this.data = new byte[64];
    this.writable = true;
  }

  /** An empty packet for {@code command}. */
  public ArNetPacket(int command) {
    this();
    setCommand(command);
  }

  private ArNetPacket(int command, byte[] data, int length) {
    this.command = command;
    this.data = data;
    this.length = length;
    this.writable = false;
  }

  /** A packet that reads the body bytes {@code body} (copied), with command 0. */
  public static ArNetPacket wrap(byte[] body) {
    return wrap(0, body, 0, body.length);
  }

  /**
   * A packet of {@code command} that reads {@code len} body bytes of {@code a} from {@code off}.
   */
  public static ArNetPacket wrap(int command, byte[] a, int off, int len) {
    if (off < 0 || len < 0 || off + len > a.length) {
      throw new IndexOutOfBoundsException(
          "slice " + off + "+" + len + " outside an array of " + a.length);
    }
    return new ArNetPacket(command, Arrays.copyOfRange(a, off, off + len), len);
  }

  // ------------------------------------------------------------------ command

  /** The command number (which data this packet is for). */
  public int getCommand() {
    return command;
  }

  /** Sets the command number (0 to 65535). */
  public void setCommand(int command) {
    if (command < 0 || command > 0xFFFF) {
      throw new IllegalArgumentException("a command number is 0..65535, not " + command);
    }
    this.command = command;
  }

  // ------------------------------------------------------------------ writing

  private void ensure(int n) {
    if (!writable) {
      throw new IllegalStateException(
          "this packet was received (or wrapped) for reading; build a new ArNetPacket to write");
    }
    if (length + n > MAX_DATA_LENGTH) {
      throw new ArNetPacketException(
          "a packet holds at most "
              + MAX_DATA_LENGTH
              + " bytes of data; send the rest in another packet");
    }
    if (length + n > data.length) {
      data = Arrays.copyOf(data, Math.min(MAX_DATA_LENGTH, Math.max(data.length * 2, length + n)));
    }
  }

  private ArNetPacket putLE(long v, int bytes) {
    ensure(bytes);
    for (int i = 0; i < bytes; i++) {
      data[length++] = (byte) (v >>> (8 * i));
    }
    return this;
  }

  /** Appends a signed byte. */
  public ArNetPacket byteToBuf(int v) {
    return putLE(v, 1);
  }

  /** Appends an unsigned byte (0..255). */
  public ArNetPacket uByteToBuf(int v) {
    return putLE(v, 1);
  }

  /** Appends a signed 2-byte integer. */
  public ArNetPacket byte2ToBuf(int v) {
    return putLE(v, 2);
  }

  /** Appends an unsigned 2-byte integer. */
  public ArNetPacket uByte2ToBuf(int v) {
    return putLE(v, 2);
  }

  /** Appends a signed 4-byte integer. */
  public ArNetPacket byte4ToBuf(int v) {
    return putLE(v, 4);
  }

  /** Appends an unsigned 4-byte integer. */
  public ArNetPacket uByte4ToBuf(long v) {
    return putLE(v, 4);
  }

  /** Appends a signed 8-byte integer. */
  public ArNetPacket byte8ToBuf(long v) {
    return putLE(v, 8);
  }

  /** Appends a boolean as an unsigned byte, 1 or 0 (ArNetworking's convention). */
  public ArNetPacket boolToBuf(boolean v) {
    return uByteToBuf(v ? 1 : 0);
  }

  /** Appends a string and its ending zero byte (null is written as the empty string). */
  public ArNetPacket strToBuf(String s) {
    byte[] b = s == null ? new byte[0] : s.getBytes(StandardCharsets.UTF_8);
    int n = b.length;
    for (int i = 0; i < b.length; i++) {
      if (b[i] == 0) {
        n = i; // A C string ends at its first zero: so does what we send.
        break;
      }
    }
    ensure(n + 1);
    System.arraycopy(b, 0, data, length, n);
    length += n;
    data[length++] = 0;
    return this;
  }

  /** Appends a double as ArNetworking does: as text, {@code %g} (see {@link #formatDouble}). */
  public ArNetPacket doubleToBuf(double v) {
    return strToBuf(formatDouble(v));
  }

  /** Appends raw bytes (an image, a file); the reader must know how many. */
  public ArNetPacket dataToBuf(byte[] bytes) {
    return dataToBuf(bytes, 0, bytes.length);
  }

  /** Appends {@code len} raw bytes of {@code bytes} from {@code off}. */
  public ArNetPacket dataToBuf(byte[] bytes, int off, int len) {
    ensure(len);
    System.arraycopy(bytes, off, data, length, len);
    length += len;
    return this;
  }

  // JAria's helpers for data ArNetworking has no layout for (see PROTOCOL.md §6): fixed widths,
  // so a reader in any language can follow the data's return description.

  /** Appends a count of the elements that follow (a ubyte4). */
  public ArNetPacket arrayToBuf(int count) {
    return uByte4ToBuf(count);
  }

  /** Appends an integer as a byte8 (JAria's layouts use it where ARIA has no layout). */
  public ArNetPacket intToBuf(long v) {
    return byte8ToBuf(v);
  }

  /** Appends a block of bytes preceded by its length (a ubyte4). */
  public ArNetPacket blobToBuf(byte[] bytes) {
    ensure(4 + bytes.length);
    uByte4ToBuf(bytes.length);
    return dataToBuf(bytes);
  }

  /** Bytes that can still be appended before the packet is full. */
  public int getWriteCapacity() {
    return MAX_DATA_LENGTH - length;
  }

  // ------------------------------------------------------------------ reading

  private long getLE(int bytes, String what) {
    if (readPos + bytes > length) {
      throw new ArNetPacketException(
          "packet "
              + command
              + " ended before its "
              + what
              + " at byte "
              + readPos
              + " of "
              + length);
    }
    long v = 0;
    for (int i = 0; i < bytes; i++) {
      v |= (data[readPos + i] & 0xFFL) << (8 * i);
    }
    readPos += bytes;
    return v;
  }

  /** Reads a signed byte. */
  public int bufToByte() {
    return (byte) getLE(1, "byte");
  }

  /** Reads an unsigned byte. */
  public int bufToUByte() {
    return (int) getLE(1, "ubyte");
  }

  /** Reads a signed 2-byte integer. */
  public int bufToByte2() {
    return (short) getLE(2, "byte2");
  }

  /** Reads an unsigned 2-byte integer. */
  public int bufToUByte2() {
    return (int) getLE(2, "ubyte2");
  }

  /** Reads a signed 4-byte integer. */
  public int bufToByte4() {
    return (int) getLE(4, "byte4");
  }

  /** Reads an unsigned 4-byte integer. */
  public long bufToUByte4() {
    return getLE(4, "ubyte4");
  }

  /** Reads a signed 8-byte integer. */
  public long bufToByte8() {
    return getLE(8, "byte8");
  }

  /** Reads an unsigned byte as a boolean (anything but 0 is true). */
  public boolean bufToBool() {
    return bufToUByte() != 0;
  }

  /**
   * Reads a string up to its ending zero byte.
   *
   * @throws ArNetPacketException if the packet ends before the zero byte
   */
  public String bufToStr() {
    for (int i = readPos; i < length; i++) {
      if (data[i] == 0) {
        String s = new String(data, readPos, i - readPos, StandardCharsets.UTF_8);
        readPos = i + 1;
        return s;
      }
    }
    throw new ArNetPacketException(
        "packet " + command + ": a string at byte " + readPos + " has no ending zero byte");
  }

  /**
   * Reads a double written as text by {@link #doubleToBuf}. "INF" and "-INF" give infinities; a
   * handler that needs a finite number must check (see {@code NumericArgs}).
   *
   * @throws ArNetPacketException if the text is not a number
   */
  public double bufToDouble() {
    String s = bufToStr().trim();
    return parseDouble(s, command);
  }

  /** Reads {@code n} raw bytes. */
  public byte[] bufToData(int n) {
    if (n < 0 || readPos + n > length) {
      throw new ArNetPacketException(
          "packet " + command + " has " + (length - readPos) + " bytes left, not " + n);
    }
    byte[] b = Arrays.copyOfRange(data, readPos, readPos + n);
    readPos += n;
    return b;
  }

  /**
   * Reads a count written by {@link #arrayToBuf}; a count larger than the bytes left (each element
   * takes at least one) is refused before anything is allocated.
   */
  public int bufToArray() {
    long n = bufToUByte4();
    if (n > getRemaining()) {
      throw new ArNetPacketException(
          "packet "
              + command
              + " announces "
              + n
              + " elements but has "
              + getRemaining()
              + " bytes");
    }
    return (int) n;
  }

  /** Reads an integer written by {@link #intToBuf}. */
  public long bufToLong() {
    return bufToByte8();
  }

  /** Reads an integer written by {@link #intToBuf} that must fit an int. */
  public int bufToInt() {
    long v = bufToByte8();
    if (v < Integer.MIN_VALUE || v > Integer.MAX_VALUE) {
      throw new ArNetPacketException("packet " + command + ": " + v + " does not fit an int");
    }
    return (int) v;
  }

  /** Reads a block written by {@link #blobToBuf}. */
  public byte[] bufToBlob() {
    long n = bufToUByte4();
    if (n > getRemaining()) {
      throw new ArNetPacketException(
          "packet " + command + " announces " + n + " bytes but has " + getRemaining());
    }
    return bufToData((int) n);
  }

  /** Starts reading from the beginning of the body again. */
  public void resetRead() {
    readPos = 0;
  }

  /** Body bytes (values written, or received). */
  public int getDataLength() {
    return length;
  }

  /** Body bytes read so far. */
  public int getDataReadLength() {
    return readPos;
  }

  /** Body bytes not read yet. */
  public int getRemaining() {
    return length - readPos;
  }

  /** Whether unread bytes remain. */
  public boolean hasMore() {
    return readPos < length;
  }

  /** A copy of the body bytes. */
  public byte[] toByteArray() {
    return Arrays.copyOf(data, length);
  }

  /** A copy of the body bytes not read yet. */
  public byte[] remainingBytes() {
    return Arrays.copyOfRange(data, readPos, length);
  }

  /** A new packet that reads this packet's body (same command), from the start. */
  public ArNetPacket toReader() {
    return new ArNetPacket(command, Arrays.copyOf(data, length), length);
  }

  // ------------------------------------------------------------------ the wire

  /**
   * The packet as it goes on the wire: sync bytes, total length (little-endian), command
   * (little-endian), the body, and the checksum (big-endian, see {@link #checksum}).
   */
  public byte[] toWire() {
    int total = HEADER_LENGTH + length + FOOTER_LENGTH;
    byte[] w = new byte[total];
    w[0] = (byte) SYNC1;
    w[1] = (byte) SYNC2;
    w[2] = (byte) total;
    w[3] = (byte) (total >>> 8);
    w[4] = (byte) command;
    w[5] = (byte) (command >>> 8);
    System.arraycopy(data, 0, w, HEADER_LENGTH, length);
    int c = checksum(w, total - FOOTER_LENGTH);
    w[total - 2] = (byte) (c >>> 8);
    w[total - 1] = (byte) c;
    return w;
  }

  /**
   * Reads one whole wire packet (as {@link #toWire} makes it) from {@code w}.
   *
   * @throws ArNetPacketException if the sync bytes, length or checksum are wrong
   */
  public static ArNetPacket fromWire(byte[] w, int off, int len) {
    if (len < HEADER_LENGTH + FOOTER_LENGTH || len > MAX_LENGTH) {
      throw new ArNetPacketException("a packet is 8.." + MAX_LENGTH + " bytes, not " + len);
    }
    if ((w[off] & 0xFF) != SYNC1 || (w[off + 1] & 0xFF) != SYNC2) {
      throw new ArNetPacketException("not an ArNetworking packet (bad sync bytes)");
    }
    int total = (w[off + 2] & 0xFF) | (w[off + 3] & 0xFF) << 8;
    if (total != len) {
      throw new ArNetPacketException("the packet says " + total + " bytes but has " + len);
    }
    byte[] whole = off == 0 && w.length == len ? w : Arrays.copyOfRange(w, off, off + len);
    int want = checksum(whole, len - FOOTER_LENGTH);
    int got = (whole[len - 2] & 0xFF) << 8 | (whole[len - 1] & 0xFF);
    if (want != got) {
      throw new ArNetPacketException(
          "bad checksum: the packet says " + got + ", its bytes give " + want);
    }
    int cmd = (whole[4] & 0xFF) | (whole[5] & 0xFF) << 8;
    return wrap(cmd, whole, HEADER_LENGTH, len - HEADER_LENGTH - FOOTER_LENGTH);
  }

  /**
   * ArNetworking's checksum over the first {@code n} bytes of a packet (header and body, not the
   * checksum itself): from the fourth byte (the length's high byte) on, 16-bit big-endian words are
   * summed modulo 65536, and a last odd byte is XORed in. ARIA drops a packet whose checksum
   * differs, so this must match it bit for bit.
   */
  public static int checksum(byte[] b, int n) {
    int c = 0;
    int i = 3;
    int left = n - 2;
    while (left > 3) {
      c += ((b[i] & 0xFF) << 8) | (b[i + 1] & 0xFF);
      c &= 0xFFFF;
      left -= 2;
      i += 2;
    }
    if (left > 0) {
      c ^= b[i] & 0xFF;
    }
    return c;
  }

  // ------------------------------------------------------------------ doubles as text

  /**
   * Formats {@code v} as C's {@code printf("%g")} does (six significant digits, trailing zeros
   * removed, exponent form for very large or small numbers), "INF" or "-INF" for infinities and
   * "nan" for NaN — the text ArNetworking puts on the wire for a double.
   */
  public static String formatDouble(double v) {
    if (Double.isNaN(v)) {
      return "nan";
    }
    if (v == Double.POSITIVE_INFINITY) {
      return "INF";
    }
    if (v == Double.NEGATIVE_INFINITY) {
      return "-INF";
    }
    if (v == 0) {
      return (1 / v < 0) ? "-0" : "0";
    }
    String e = String.format(Locale.ROOT, "%.5e", v);
    int exp = Integer.parseInt(e.substring(e.indexOf('e') + 1));
    String out;
    if (exp < -4 || exp >= 6) {
      String mant = stripZeros(e.substring(0, e.indexOf('e')));
      String sign = exp < 0 ? "-" : "+";
      int a = Math.abs(exp);
      out = mant + "e" + sign + (a < 10 ? "0" : "") + a;
    } else {
      out = stripZeros(String.format(Locale.ROOT, "%." + (5 - exp) + "f", v));
    }
    return out;
  }

  private static String stripZeros(String s) {
    if (s.indexOf('.') < 0) {
      return s;
    }
    int end = s.length();
    while (s.charAt(end - 1) == '0') {
      end--;
    }
    if (s.charAt(end - 1) == '.') {
      end--;
    }
    return s.substring(0, end);
  }

  /** Parses a double's text as {@link #bufToDouble} does. */
  static double parseDouble(String s, int command) {
    if (s.equals("INF") || s.equals("inf")) {
      return Double.POSITIVE_INFINITY;
    }
    if (s.equals("-INF") || s.equals("-inf")) {
      return Double.NEGATIVE_INFINITY;
    }
    if (s.equalsIgnoreCase("nan") || s.equalsIgnoreCase("-nan")) {
      return Double.NaN;
    }
    if (s.isEmpty() || s.length() > 64 || !s.matches("[-+0-9.eE]+")) {
      throw new ArNetPacketException(
          "packet " + command + ": '" + abbreviate(s) + "' is not a number");
    }
    try {
      return Double.parseDouble(s);
    } catch (NumberFormatException e) {
      throw new ArNetPacketException(
          "packet " + command + ": '" + abbreviate(s) + "' is not a number", e);
    }
  }

  private static String abbreviate(String s) {
    return s.length() > 32 ? s.substring(0, 32) + "..." : s;
  }

  @Override
  public String toString() {
    StringBuilder sb = new StringBuilder("ArNetPacket[command " + command + ", " + length + " B:");
    for (int i = 0; i < Math.min(length, 32); i++) {
      sb.append(String.format(Locale.ROOT, " %02x", data[i]));
    }
    return sb.append(length > 32 ? " ...]" : "]").toString();
  }
}
