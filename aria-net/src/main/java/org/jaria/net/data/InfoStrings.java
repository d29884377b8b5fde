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

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(labels.size());
    for (int i = 0; i < labels.size(); i++) {
      out.arrayToBuf(2).strToBuf(labels.get(i)).strToBuf(values.get(i));
    }
  }

  /** Reads what {@link #write} wrote. */
  public static InfoStrings read(ArNetPacket in) {
    int n = in.bufToArray();
    List<String> l = new ArrayList<>(n);
    List<String> v = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      int k = Fields.begin(in, 2, "an info string");
      l.add(nonNull(in.bufToStr()));
      v.add(nonNull(in.bufToStr()));
      Fields.end(in, k, 2);
    }
    return new InfoStrings(l, v);
  }

  private static String nonNull(String s) {
    if (s == null) {
      throw new ArNetPacketException("an info string label or value is nil");
    }
    return s;
  }
}
