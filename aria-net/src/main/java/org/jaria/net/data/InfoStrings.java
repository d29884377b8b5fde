package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;

/**
 * The custom information table ({@code "getStrings"}, ArNetworking's {@code ArServerInfoStrings}):
 * labelled values a program wants operators to see ("Sonar Localization Score: 0.812").
 *
 * @param labels the labels, in order
 * @param values the values, one per label
 */
public record InfoStrings(List<String> labels, List<String> values) implements NetEncodable {

  /** Copies the lists and checks they match. */
  public InfoStrings {
    labels = List.copyOf(labels);
    values = List.copyOf(values);
    if (labels.size() != values.size()) {
      throw new IllegalArgumentException("one value per label");
    }
  }

  /** The value of {@code label}, or null. */
  public String get(String label) {
    int i = labels.indexOf(label);
    return i < 0 ? null : values.get(i);
  }

  /** Writes ArNetworking's {@code "getStrings"} layout: the values, one string each, in order. */
  @Override
  public void write(ArNetPacket out) {
    for (String v : values) {
      out.strToBuf(v);
    }
  }

  /**
   * Reads a {@code "getStrings"} packet: one value per string to the end of the packet, labelled in
   * order with {@code labels} (from {@link #readLabels}); a value beyond the labels is labelled "#"
   * and its position, as the server's table changed since the labels were read.
   */
  public static InfoStrings read(ArNetPacket in, List<String> labels) {
    List<String> l = new ArrayList<>();
    List<String> v = new ArrayList<>();
    while (in.hasMore()) {
      int i = v.size();
      v.add(nonNull(in.bufToStr()));
      l.add(i < labels.size() ? labels.get(i) : "#" + (i + 1));
    }
    return new InfoStrings(l, v);
  }

  /** The same values labelled with {@code newLabels} (as {@link #read} labels them). */
  public InfoStrings withLabels(List<String> newLabels) {
    List<String> l = new ArrayList<>();
    for (int i = 0; i < values.size(); i++) {
      l.add(i < newLabels.size() ? newLabels.get(i) : "#" + (i + 1));
    }
    return new InfoStrings(l, values);
  }

  /**
   * Reads a {@code "getStringsInfo"} packet (uByte2 count; per string: string name, uByte2 maximum
   * length) as the labels, in order.
   */
  public static List<String> readLabels(ArNetPacket in) {
    int n = in.bufToUByte2();
    List<String> l = new ArrayList<>(Math.min(n, 1024));
    for (int i = 0; i < n; i++) {
      l.add(nonNull(in.bufToStr()));
      in.bufToUByte2();
    }
    return l;
  }

  private static String nonNull(String s) {
    if (s == null) {
      throw new ArNetPacketException("an info string label or value is nil");
    }
    return s;
  }
}
