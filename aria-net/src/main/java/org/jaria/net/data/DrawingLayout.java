package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * ArNetworking's layouts for drawings ({@code ArServerInfoDrawings}), written and read:
 *
 * <ul>
 *   <li>{@code listDrawings}: byte4 count, then per drawing string name, string shape, byte4
 *       primary colour (0RGB), byte4 size, byte4 layer, ubyte4 refresh time (ms), byte4 secondary
 *       colour;
 *   <li>{@code getDrawingList}: one packet per drawing with the same fields plus string visibility,
 *       then an empty packet;
 *   <li>a drawing's own data: byte4 count, then byte4 x, byte4 y per point (mm, map coordinates).
 * </ul>
 *
 * Reading is strict: a count larger than the packet can hold, a negative count or a packet cut
 * short is an {@link ArNetPacketException}.
 */
public final class DrawingLayout {

  /** Bytes of a point on the wire (two byte4). */
  private static final int POINT_BYTES = 8;

  /**
   * The fewest bytes one drawing takes in {@code listDrawings}: two empty strings, five numbers.
   */
  private static final int LISTED_MIN_BYTES = 2 + 5 * 4;

  private DrawingLayout() {}

  /** Writes the {@code listDrawings} answer. */
  public static void writeList(ArNetPacket out, List<NamedDrawing> drawings) {
    out.byte4ToBuf(drawings.size());
    for (NamedDrawing d : drawings) {
      writeCommon(out, d);
    }
  }

  /**
   * Reads a {@code listDrawings} answer (visibility is {@code DefaultOn}: that layout has none).
   */
  public static List<NamedDrawing> readList(ArNetPacket in) {
    int n = in.bufToByte4();
    if (n < 0 || (long) n * LISTED_MIN_BYTES > in.getRemaining()) {
      throw new ArNetPacketException(
          "listDrawings announces " + n + " drawings but has " + in.getRemaining() + " bytes");
    }
    List<NamedDrawing> l = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      l.add(readCommon(in, "DefaultOn"));
    }
    return l;
  }

  /** Writes one {@code getDrawingList} packet. */
  public static void writeListed(ArNetPacket out, NamedDrawing d) {
    writeCommon(out, d);
    out.strToBuf(d.data().visibility());
  }

  /**
   * Reads one {@code getDrawingList} packet.
   *
   * @return the drawing, or null for the empty packet that ends the list
   */
  public static NamedDrawing readListed(ArNetPacket in) {
    if (!in.hasMore()) {
      return null;
    }
    String name = in.bufToStr();
    ArDrawingData partial = readData(in, "");
    return new NamedDrawing(
        name,
        new ArDrawingData(
            partial.shape(),
            partial.primaryColor(),
            partial.size(),
            partial.layer(),
            partial.defaultRefreshTime(),
            partial.secondaryColor(),
            in.bufToStr()));
  }

  /**
   * Reads a whole {@code getDrawingList} answer: the packets' bodies one after the other (as a
   * client gathers a RETURN_UNTIL_EMPTY answer), or one packet.
   */
  public static List<NamedDrawing> readAllListed(ArNetPacket in) {
    List<NamedDrawing> l = new ArrayList<>();
    NamedDrawing d;
    while ((d = readListed(in)) != null) {
      l.add(d);
    }
    return l;
  }

  /** Writes a drawing's points. */
  public static void writePoints(ArNetPacket out, Points points) {
    out.byte4ToBuf(points.size());
    for (int i = 0; i < points.size(); i++) {
      out.byte4ToBuf(points.x(i)).byte4ToBuf(points.y(i));
    }
  }

  /** Reads a drawing's points. */
  public static Points readPoints(ArNetPacket in) {
    int n = in.bufToByte4();
    if (n < 0 || (long) n * POINT_BYTES > in.getRemaining()) {
      throw new ArNetPacketException(
          "a drawing announces " + n + " points but has " + in.getRemaining() + " bytes");
    }
    int[] v = new int[n * 2];
    for (int i = 0; i < v.length; i++) {
      v[i] = in.bufToByte4();
    }
    return Points.ofFlat(v, 2);
  }

  private static void writeCommon(ArNetPacket out, NamedDrawing d) {
    ArDrawingData a = d.data();
    out.strToBuf(d.name())
        .strToBuf(a.shape())
        .byte4ToBuf(a.primaryColor())
        .byte4ToBuf(a.size())
        .byte4ToBuf(a.layer())
        .uByte4ToBuf(a.defaultRefreshTime())
        .byte4ToBuf(a.secondaryColor());
  }

  private static NamedDrawing readCommon(ArNetPacket in, String visibility) {
    String name = in.bufToStr();
    return new NamedDrawing(name, readData(in, visibility));
  }

  private static ArDrawingData readData(ArNetPacket in, String visibility) {
    String shape = in.bufToStr();
    int primary = in.bufToByte4();
    int size = in.bufToByte4();
    int layer = in.bufToByte4();
    long refresh = in.bufToUByte4();
    int secondary = in.bufToByte4();
    return new ArDrawingData(shape, primary, size, layer, refresh, secondary, visibility);
  }
}
