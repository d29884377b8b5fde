package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * ArNetworking's {@code getMapBinary} layout (RETURN_UNTIL_EMPTY): the map's header and objects as
 * text, one line per packet; then, if the map has lines, a packet {@code "LINES"} and packets of
 * byte4 count and count × (byte4 x1, y1, x2, y2), ended by a packet with count 0; then a packet
 * {@code "DATA"} and packets of byte4 count and count × (byte4 x, y), ended by count 0; then the
 * empty packet. At most 1000 lines or points go in one packet, as in ArNetworking.
 *
 * <p>{@link #bodies} makes the packets' bodies from a map's text (its .map file); {@link #readText}
 * reads them back — one after the other, as a client gathers them — into .map text.
 */
public final class MapBinaryLayout {

  /** Most lines or points in one packet (ArNetworking's). */
  public static final int PER_PACKET = 1000;

  private MapBinaryLayout() {}

  /**
   * The packet bodies of a map, without the final empty packet.
   *
   * @throws IllegalArgumentException if a LINES or DATA line of {@code mapText} is not numbers
   */
  public static List<ArNetPacket> bodies(String mapText) {
    List<String> header = new ArrayList<>();
    List<int[]> lines = new ArrayList<>();
    List<int[]> points = new ArrayList<>();
    List<int[]> target = null;
    for (String raw : mapText.split("\n", -1)) {
      String line = raw.strip();
      if (line.isEmpty()) {
        continue;
      }
      if (line.equals("LINES")) {
        target = lines;
      } else if (line.equals("DATA")) {
        target = points;
      } else if (target == null) {
        header.add(line);
      } else {
        target.add(numbers(line, target == lines ? 4 : 2));
      }
    }
    List<ArNetPacket> out = new ArrayList<>();
    for (String h : header) {
      out.add(new ArNetPacket().strToBuf(h.length() > 4000 ? h.substring(0, 4000) : h));
    }
    if (!lines.isEmpty()) {
      out.add(new ArNetPacket().strToBuf("LINES"));
      chunks(lines, out);
    }
    out.add(new ArNetPacket().strToBuf("DATA"));
    chunks(points, out);
    return out;
  }

  private static int[] numbers(String line, int n) {
    String[] f = line.split("\\s+", -1);
    if (f.length < n) {
      throw new IllegalArgumentException("a map line needs " + n + " numbers: '" + line + "'");
    }
    int[] v = new int[n];
    for (int i = 0; i < n; i++) {
      v[i] = (int) Math.round(Double.parseDouble(f[i]));
    }
    return v;
  }

  private static void chunks(List<int[]> items, List<ArNetPacket> out) {
    for (int i = 0; i < items.size(); i += PER_PACKET) {
      List<int[]> part = items.subList(i, Math.min(items.size(), i + PER_PACKET));
      ArNetPacket p = new ArNetPacket().byte4ToBuf(part.size());
      for (int[] v : part) {
        for (int x : v) {
          p.byte4ToBuf(x);
        }
      }
      out.add(p);
    }
    out.add(new ArNetPacket().byte4ToBuf(0));
  }

  /**
   * Reads the bodies of a {@code getMapBinary} answer, joined, back into .map text.
   *
   * @throws ArNetPacketException if it is cut short, a count is negative or larger than the bytes
   *     left, or the points never start
   */
  public static String readText(ArNetPacket in) {
    StringBuilder text = new StringBuilder();
    String s;
    while (true) {
      if (!in.hasMore()) {
        return text.toString(); // no map ("") or a map without DATA
      }
      s = in.bufToStr();
      if (s.equals("LINES") || s.equals("DATA") || s.isEmpty()) {
        break;
      }
      text.append(s).append('\n');
    }
    if (s.equals("LINES")) {
      text.append("LINES\n");
      readNumbers(in, 4, text);
      s = in.bufToStr();
    }
    if (s.equals("DATA")) {
      text.append("DATA\n");
      readNumbers(in, 2, text);
    }
    return text.toString();
  }

  private static void readNumbers(ArNetPacket in, int per, StringBuilder text) {
    while (true) {
      int n = in.bufToByte4();
      if (n == 0) {
        return;
      }
      if (n < 0 || (long) n * per * 4 > in.getRemaining()) {
        throw new ArNetPacketException(
            "getMapBinary announces " + n + " items but has " + in.getRemaining() + " bytes");
      }
      for (int i = 0; i < n; i++) {
        for (int k = 0; k < per; k++) {
          text.append(String.format(Locale.ROOT, k == 0 ? "%d" : " %d", in.bufToByte4()));
        }
        text.append('\n');
      }
    }
  }
}
