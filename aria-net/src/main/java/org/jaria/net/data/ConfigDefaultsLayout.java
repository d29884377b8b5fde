package org.jaria.net.data;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * ArNetworking's layout of {@code getConfigDefaults}'s answer: pairs of strings to the end of the
 * packet, the same pairs {@code setConfig} takes — ({@code "Section"}, section name) starts a
 * section, then (parameter name, default value as text) for each of its parameters. The request
 * takes one optional string, a section's name; without it (or with "") every section is sent.
 */
public final class ConfigDefaultsLayout {

  /** The parameter name that starts a section. */
  public static final String SECTION = "Section";

  private ConfigDefaultsLayout() {}

  /**
   * Writes the defaults of {@code sections}: all of them if {@code onlySection} is empty, else only
   * the section of that name (ignoring case).
   */
  public static void write(ArNetPacket out, List<ConfigSection> sections, String onlySection) {
    for (ConfigSection s : sections) {
      if (!onlySection.isEmpty() && !onlySection.equalsIgnoreCase(s.name())) {
        continue;
      }
      out.strToBuf(SECTION).strToBuf(s.name());
      for (ConfigParam p : s.params()) {
        out.strToBuf(p.name()).strToBuf(p.defaultValue());
      }
    }
  }

  /**
   * Reads the answer: section name to (parameter name to default), in the order sent.
   *
   * @throws ArNetPacketException if a name has no value, or a parameter comes before any section
   */
  public static Map<String, Map<String, String>> read(ArNetPacket in) {
    Map<String, Map<String, String>> out = new LinkedHashMap<>();
    Map<String, String> current = null;
    while (in.hasMore()) {
      String name = in.bufToStr();
      String value = in.bufToStr();
      if (name.equalsIgnoreCase(SECTION)) {
        current = out.computeIfAbsent(value, k -> new LinkedHashMap<>());
      } else if (current == null) {
        throw new ArNetPacketException(
            "configuration defaults give parameter '" + name + "' before any section");
      } else {
        current.put(name, value);
      }
    }
    return out;
  }

  /** The section names of an answer read by {@link #read}. */
  public static List<String> sectionNames(Map<String, Map<String, String>> read) {
    return new ArrayList<>(read.keySet());
  }
}
