package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * A section of the configuration with its parameters.
 *
 * @param name the section's name ("Teleop settings", "Localization" ...)
 * @param comment what the section is for
 * @param params its parameters
 */
public record ConfigSection(String name, String comment, List<ConfigParam> params)
    implements NetEncodable {

  /** Copies the list. */
  public ConfigSection {
    params = List.copyOf(params);
  }

  /** Writes a list of sections as one array. */
  public static void writeAll(ArNetPacket out, List<ConfigSection> sections) {
    out.arrayToBuf(sections.size());
    for (ConfigSection s : sections) {
      s.write(out);
    }
  }

  /** Reads what {@link #writeAll} wrote. */
  public static List<ConfigSection> readAll(ArNetPacket in) {
    int n = in.bufToArray();
    List<ConfigSection> l = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      l.add(read(in));
    }
    return l;
  }

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(3).strToBuf(name).strToBuf(comment).arrayToBuf(params.size());
    for (ConfigParam p : params) {
      p.write(out);
    }
  }

  /** Reads what {@link #write} wrote. */
  public static ConfigSection read(ArNetPacket in) {
    int n = Fields.begin(in, 3, "a configuration section");
    String name = in.bufToStr();
    String comment = in.bufToStr();
    int k = in.bufToArray();
    List<ConfigParam> l = new ArrayList<>(k);
    for (int i = 0; i < k; i++) {
      l.add(ConfigParam.read(in));
    }
    Fields.end(in, n, 3);
    return new ConfigSection(name, comment, l);
  }
}
