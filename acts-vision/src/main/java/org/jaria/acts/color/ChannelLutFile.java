package org.jaria.acts.color;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;
import java.util.zip.CRC32;
import org.jaria.acts.ActsFormatException;

/**
 * Reads and writes channel lookup-table files ({@code channelN.lut} by default): one {@link
 * Channel} per file. A file written by ACTS itself is not readable (its format was never
 * published); this is JAria's own format.
 *
 * <h2>Format, version 1</h2>
 *
 * <p>An ASCII header of {@code '\n'}-terminated lines, a block of raw bytes, and a checksum line:
 *
 * <pre>
 * JARIA-ACTS-LUT 1
 * # any number of comment lines starting with '#'
 * cells 256
 * limits RG 0 0 0 510
 * limits BG 0 0 0 510
 * limits RB 0 0 0 510
 * planes 24576
 * &lt;24576 bytes&gt;
 * crc32 89ABCDEF
 * </pre>
 *
 * <ul>
 *   <li>{@code cells N}: cells per plane axis, a power of two from 16 to 256 (a colour value {@code
 *       v} falls in cell {@code v * N / 256}).
 *   <li>{@code limits P first second low high}: the manual limits of plane {@code P} (RG, BG, RB,
 *       in that order), see {@link PlaneLimits}.
 *   <li>{@code planes L}: {@code L = 3 * N * N / 8} bytes follow, then a {@code '\n'}: the RG, BG
 *       and RB planes one after another. In a plane, cell {@code (a, b)} (a = first colour, b =
 *       second) is bit number {@code a * N + b}; bit {@code k} is bit {@code k % 8} (least
 *       significant first) of byte {@code k / 8}.
 *   <li>{@code crc32 H}: 8 hexadecimal digits, the CRC-32 of every byte before this line.
 * </ul>
 *
 * <p>Reading is all or nothing: a damaged file (bad header, wrong sizes, truncated data, checksum
 * mismatch) throws an {@link ActsFormatException} naming the file and line or byte offset, and no
 * channel is changed. Writing goes through a temporary file, so a crash never leaves half a file.
 */
public final class ChannelLutFile {

  /** First line of every file. */
  public static final String MAGIC = "JARIA-ACTS-LUT 1";

  /** Files larger than this are rejected before reading (a 256-cell file is about 24 KB). */
  public static final int MAX_FILE_BYTES = 1 << 20;

  private static final int MAX_LINE = 200;

  private ChannelLutFile() {}

  // ---------------------------------------------------------------- writing

  /** The file's bytes for a channel. */
  public static byte[] toBytes(Channel channel) {
    int n = channel.cellsPerAxis();
    StringBuilder head = new StringBuilder();
    head.append(MAGIC).append('\n');
    head.append(
        "# JAria ACTS channel lookup table (format: see org.jaria.acts.color.ChannelLutFile)\n");
    head.append("cells ").append(n).append('\n');
    for (ColorPlane p : ColorPlane.all()) {
      PlaneLimits l = channel.getLimits(p);
      head.append("limits ")
          .append(p.name())
          .append(' ')
          .append(l.firstColor())
          .append(' ')
          .append(l.secondColor())
          .append(' ')
          .append(l.lowBright())
          .append(' ')
          .append(l.highBright())
          .append('\n');
    }
    int planeBytes = n * n / 8;
    head.append("planes ").append(3 * planeBytes).append('\n');
    ByteArrayOutputStream out = new ByteArrayOutputStream(3 * planeBytes + 256);
    out.writeBytes(head.toString().getBytes(StandardCharsets.US_ASCII));
    for (ColorPlane p : ColorPlane.all()) {
      long[] words = channel.words(p);
      for (int i = 0; i < planeBytes; i++) {
        out.write((int) (words[i >>> 3] >>> ((i & 7) * 8)) & 0xFF);
      }
    }
    out.write('\n');
    CRC32 crc = new CRC32();
    byte[] body = out.toByteArray();
    crc.update(body);
    out.writeBytes(
        (String.format(Locale.ROOT, "crc32 %08X", crc.getValue()) + "\n")
            .getBytes(StandardCharsets.US_ASCII));
    return out.toByteArray();
  }

  /** Writes a channel to {@code file} (atomically, via a temporary file in the same folder). */
  public static void write(Channel channel, Path file) throws IOException {
    Path abs = file.toAbsolutePath();
    Path dir = abs.getParent();
    Path tmp = Files.createTempFile(dir, abs.getFileName().toString(), ".tmp");
    try {
      Files.write(tmp, toBytes(channel));
      try {
        Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
      } catch (AtomicMoveNotSupportedException e) {
        Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
      }
    } finally {
      Files.deleteIfExists(tmp);
    }
  }

  // ---------------------------------------------------------------- reading

  /** Reads a channel from {@code file}. */
  public static Channel read(Path file) throws IOException {
    long size = Files.size(file);
    if (size > MAX_FILE_BYTES) {
      throw new ActsFormatException(
          file.toString(),
          -1,
          "is " + size + " bytes, too large for a channel LUT file; is it the right file?");
    }
    return parse(Files.readAllBytes(file), file.toString());
  }

  /** Reads a channel from a stream (at most {@link #MAX_FILE_BYTES} bytes are read). */
  public static Channel read(InputStream in, String name) throws IOException {
    byte[] data = in.readNBytes(MAX_FILE_BYTES + 1);
    if (data.length > MAX_FILE_BYTES) {
      throw new ActsFormatException(name, -1, "is too large for a channel LUT file");
    }
    return parse(data, name);
  }

  /**
   * Parses the bytes of a channel file.
   *
   * @param name the file name for messages
   * @throws ActsFormatException if the bytes are not a valid channel file
   */
  public static Channel parse(byte[] data, String name) throws ActsFormatException {
    Reader r = new Reader(data, name);
    String magic = r.line();
    if (!magic.equals(MAGIC)) {
      throw r.error(
          "not a JAria channel LUT file (first line should be '"
              + MAGIC
              + "'); load a file saved by JAria's EZ-Train or 'jaria acts'");
    }
    String line = r.lineSkippingComments();
    String[] f = fields(line);
    if (f.length != 2 || !f[0].equals("cells")) {
      throw r.error("expected 'cells N', found '" + shorten(line) + "'");
    }
    int cells = r.number(f[1], 16, 256, "cells");
    int bits = Integer.numberOfTrailingZeros(cells);
    if (Integer.bitCount(cells) != 1) {
      throw r.error("cells must be a power of two (16, 32, 64, 128 or 256), got " + cells);
    }
    Channel channel = new Channel(bits);
    for (ColorPlane p : ColorPlane.all()) {
      line = r.line();
      f = fields(line);
      if (f.length != 6 || !f[0].equals("limits") || !f[1].equals(p.name())) {
        throw r.error(
            "expected 'limits "
                + p.name()
                + " first second low high', found '"
                + shorten(line)
                + "'");
      }
      channel.setLimits(
          p,
          new PlaneLimits(
              r.number(f[2], 0, 90, "first colour limit"),
              r.number(f[3], 0, 90, "second colour limit"),
              r.number(f[4], 0, PlaneLimits.MAX_BRIGHT, "low bright limit"),
              r.number(f[5], 0, PlaneLimits.MAX_BRIGHT, "high bright limit")));
    }
    line = r.line();
    f = fields(line);
    int planeBytes = cells * cells / 8;
    if (f.length != 2 || !f[0].equals("planes")) {
      throw r.error("expected 'planes " + 3 * planeBytes + "', found '" + shorten(line) + "'");
    }
    int declared = r.number(f[1], 0, Integer.MAX_VALUE, "plane byte count");
    if (declared != 3 * planeBytes) {
      throw r.error(
          "says "
              + declared
              + " plane bytes but "
              + cells
              + " cells per axis need "
              + 3 * planeBytes);
    }
    int dataStart = r.pos;
    if (data.length - dataStart < 3 * planeBytes + 1) {
      throw atByte(
          name,
          data.length,
          "truncated: the planes need "
              + 3 * planeBytes
              + " bytes from offset "
              + dataStart
              + " but the file ends first; the file is damaged, train the channel again or use a"
              + " backup");
    }
    for (ColorPlane p : ColorPlane.all()) {
      long[] words = channel.words(p);
      int base = dataStart + p.ordinal() * planeBytes;
      for (int i = 0; i < planeBytes; i++) {
        words[i >>> 3] |= (data[base + i] & 0xFFL) << ((i & 7) * 8);
      }
    }
    r.pos = dataStart + 3 * planeBytes;
    if (data[r.pos] != '\n') {
      throw atByte(name, r.pos, "expected end of line after the plane bytes; the file is damaged");
    }
    int crcEnd = ++r.pos;
    int lineEnd = r.pos;
    while (lineEnd < data.length && data[lineEnd] != '\n' && lineEnd - r.pos <= MAX_LINE) {
      lineEnd++;
    }
    String crcLine =
        new String(data, r.pos, lineEnd - r.pos, StandardCharsets.ISO_8859_1).replace("\r", "");
    f = fields(crcLine);
    if (lineEnd >= data.length
        || f.length != 2
        || !f[0].equals("crc32")
        || !f[1].matches("[0-9A-Fa-f]{8}")) {
      throw atByte(
          name,
          crcEnd,
          "expected the line 'crc32 XXXXXXXX' after the planes, found '"
              + shorten(crcLine)
              + "'; the file is damaged or truncated");
    }
    long stored = Long.parseLong(f[1], 16);
    CRC32 crc = new CRC32();
    crc.update(data, 0, crcEnd);
    if (crc.getValue() != stored) {
      throw atByte(
          name,
          crcEnd,
          String.format(
              Locale.ROOT,
              "checksum mismatch (file says %08X, contents give %08X): the file is damaged;"
                  + " train the channel again or use a backup",
              stored,
              crc.getValue()));
    }
    if (lineEnd + 1 != data.length) {
      throw atByte(name, lineEnd + 1, "unexpected data after the checksum line");
    }
    return channel;
  }

  private static ActsFormatException atByte(String name, int offset, String message) {
    return new ActsFormatException(name, -1, "at byte " + offset + ": " + message);
  }

  private static String[] fields(String line) {
    String t = line.strip();
    return t.isEmpty() ? new String[0] : t.split("[ \t]+", -1);
  }

  private static String shorten(String s) {
    StringBuilder b = new StringBuilder();
    for (int i = 0; i < s.length() && b.length() < 40; i++) {
      char c = s.charAt(i);
      b.append(c >= 32 && c < 127 ? c : '?');
    }
    return s.length() > 40 ? b + "..." : b.toString();
  }

  /** A cursor over the header lines. */
  private static final class Reader {
    final byte[] data;
    final String name;
    int pos;
    int line;

    Reader(byte[] data, String name) {
      this.data = data;
      this.name = name;
    }

    String line() throws ActsFormatException {
      line++;
      int start = pos;
      while (pos < data.length && data[pos] != '\n') {
        if (pos - start > MAX_LINE) {
          throw error("line too long; the file is damaged or not a channel LUT file");
        }
        pos++;
      }
      if (pos >= data.length) {
        throw error("file ends in the middle of the header; the file is truncated");
      }
      int end = pos++;
      if (end > start && data[end - 1] == '\r') {
        end--;
      }
      for (int i = start; i < end; i++) {
        if ((data[i] < 0x20 && data[i] != '\t') || data[i] >= 0x7F) {
          throw error("binary data in the header; the file is damaged or not a channel LUT file");
        }
      }
      return new String(data, start, end - start, StandardCharsets.US_ASCII);
    }

    String lineSkippingComments() throws ActsFormatException {
      String s = line();
      while (s.startsWith("#")) {
        s = line();
      }
      return s;
    }

    int number(String text, int min, int max, String what) throws ActsFormatException {
      try {
        int v = Integer.parseInt(text);
        if (v < min || v > max) {
          throw error(what + " must be " + min + ".." + max + ", got " + v);
        }
        return v;
      } catch (NumberFormatException e) {
        throw error(what + " '" + shorten(text) + "' is not a whole number");
      }
    }

    ActsFormatException error(String message) {
      return new ActsFormatException(name, line, message);
    }
  }
}
