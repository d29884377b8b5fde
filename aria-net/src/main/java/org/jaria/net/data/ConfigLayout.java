package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * ArNetworking's first layout of {@code "getConfigBySections"}: one packet per section, a byte
 * {@code 'S'} with the section's name and comment, then per parameter a byte {@code 'P'}, its name,
 * description, a priority byte, a type letter ({@code 'b'} byte value, {@code 'i'} three 4-byte
 * integers value/min/max, {@code 'd'} three doubles as text, {@code 's'} a string) and a display
 * hint. The version 1 layout carries no default values, so {@link ConfigParam#defaultValue} reads
 * back empty.
 */
public final class ConfigLayout {

  /** ArPriority's BASIC: every client shows the parameter. */
  private static final int PRIORITY_BASIC = 0;

  private ConfigLayout() {}

  /** Writes one section as the payload of one packet. */
  public static void writeSection(ArNetPacket out, ConfigSection s) {
    out.byteToBuf('S').strToBuf(s.name()).strToBuf(s.comment());
    for (ConfigParam p : s.params()) {
      out.byteToBuf('P').strToBuf(p.name()).strToBuf(p.description()).byteToBuf(PRIORITY_BASIC);
      switch (p.type()) {
        case "BOOL" -> out.byteToBuf('b').byteToBuf(Boolean.parseBoolean(p.value()) ? 1 : 0);
        case "INT" ->
            out.byteToBuf('i')
                .byte4ToBuf(Integer.parseInt(p.value()))
                .byte4ToBuf(p.min().isEmpty() ? Integer.MIN_VALUE : toInt(p.min()))
                .byte4ToBuf(p.max().isEmpty() ? Integer.MAX_VALUE : toInt(p.max()));
        case "DOUBLE" ->
            out.byteToBuf('d')
                .doubleToBuf(Double.parseDouble(p.value()))
                .doubleToBuf(p.min().isEmpty() ? Double.NEGATIVE_INFINITY : toDouble(p.min()))
                .doubleToBuf(p.max().isEmpty() ? Double.POSITIVE_INFINITY : toDouble(p.max()));
        default -> out.byteToBuf('s').strToBuf(p.value());
      }
      out.strToBuf(""); // display hint
    }
  }

  /**
   * Reads the sections from the gathered packets of one answer (the client joins the packets of a
   * RETURN_UNTIL_EMPTY reply into one reader).
   *
   * @throws ArNetPacketException if a record is not a section or parameter of this layout
   */
  public static List<ConfigSection> readAll(ArNetPacket in) {
    List<ConfigSection> sections = new ArrayList<>();
    String name = null;
    String comment = "";
    List<ConfigParam> params = new ArrayList<>();
    while (in.hasMore()) {
      int kind = in.bufToByte();
      if (kind == 'S') {
        if (name != null) {
          sections.add(new ConfigSection(name, comment, params));
        }
        name = in.bufToStr();
        comment = in.bufToStr();
        params = new ArrayList<>();
      } else if (kind == 'P' && name != null) {
        ConfigParam p = readParam(in);
        if (p != null) {
          params.add(p);
        }
      } else {
        throw new ArNetPacketException(
            "not ArNetworking's getConfigBySections layout: record kind " + kind);
      }
    }
    if (name != null) {
      sections.add(new ConfigSection(name, comment, params));
    }
    return sections;
  }

  /**
   * One parameter, or null for what is not a value to edit: a separator ('.'), or a list ('l'),
   * whose items are read past. A lower-case type letter is followed by a display hint, an
   * upper-case one (from a server that parses no display hints) is not; a separator carries one.
   */
  private static ConfigParam readParam(ArNetPacket in) {
    String name = in.bufToStr();
    String description = in.bufToStr();
    in.bufToByte(); // priority
    int letter = in.bufToByte();
    boolean hinted = Character.isLowerCase(letter) || letter == '.';
    int type = Character.toLowerCase(letter);
    ConfigParam p =
        switch (type) {
          case '.' -> null;
          case 'l' -> {
            int items = in.bufToByte4();
            if (items < 0 || items > in.getRemaining()) {
              throw new ArNetPacketException(
                  "configuration list " + name + " announces " + items + " items");
            }
            for (int i = 0; i < items; i++) {
              readParam(in);
            }
            yield null;
          }
          case 'b' ->
              new ConfigParam(
                  name, "BOOL", Boolean.toString(in.bufToByte() != 0), "", "", "", description);
          case 'i' -> {
            int v = in.bufToByte4();
            int min = in.bufToByte4();
            int max = in.bufToByte4();
            yield new ConfigParam(
                name,
                "INT",
                Integer.toString(v),
                "",
                min == Integer.MIN_VALUE ? "" : Integer.toString(min),
                max == Integer.MAX_VALUE ? "" : Integer.toString(max),
                description);
          }
          case 'd' -> {
            double v = in.bufToDouble();
            double min = in.bufToDouble();
            double max = in.bufToDouble();
            yield new ConfigParam(
                name,
                "DOUBLE",
                Double.toString(v),
                "",
                Double.isInfinite(min) ? "" : Double.toString(min),
                Double.isInfinite(max) ? "" : Double.toString(max),
                description);
          }
          case 's' -> new ConfigParam(name, "STRING", in.bufToStr(), "", "", "", description);
          default ->
              throw new ArNetPacketException(
                  "configuration parameter " + name + " has a type this reader lacks: " + type);
        };
    if (hinted) {
      in.bufToStr(); // display hint
    }
    return p;
  }

  private static int toInt(String s) {
    return (int) Math.round(Double.parseDouble(s));
  }

  private static double toDouble(String s) {
    return Double.parseDouble(s);
  }
}
