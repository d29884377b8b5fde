package org.jaria.net.guiserver;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import org.jaria.net.data.ConfigParam;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.provider.ConfigRegistry;

/**
 * A configuration with ARIA's {@code Files} section in front: its one parameter, {@code Map}, names
 * the map the server uses, and setting it changes the map (what ARIA's {@code changeMapOnServer}
 * and MobileEyes do). Every other section is the wrapped configuration's.
 */
final class FilesConfig implements ConfigRegistry {

  /** The section's name, as ARIA's. */
  static final String SECTION = "Files";

  /** The parameter's name, as ARIA's. */
  static final String MAP = "Map";

  private final ConfigRegistry base;
  private final Supplier<String> mapName;
  private final UnaryOperator<String> changeMap;

  /**
   * @param mapName the map's name now
   * @param changeMap changes to the map named, returning null or why not
   */
  FilesConfig(ConfigRegistry base, Supplier<String> mapName, UnaryOperator<String> changeMap) {
    this.base = base;
    this.mapName = mapName;
    this.changeMap = changeMap;
  }

  @Override
  public List<ConfigSection> getSections() {
    List<ConfigSection> l = new ArrayList<>();
    l.add(
        new ConfigSection(
            SECTION,
            "The files where important data is stored",
            List.of(
                new ConfigParam(
                    MAP,
                    "STRING",
                    mapName.get(),
                    "",
                    "",
                    "",
                    "Map of the environment that the robot uses for navigation"))));
    l.addAll(base.getSections());
    return l;
  }

  @Override
  public String setParam(String section, String name, String valueText) {
    if (!section.equalsIgnoreCase(SECTION)) {
      return base.setParam(section, name, valueText);
    }
    if (!name.equalsIgnoreCase(MAP)) {
      return "section '" + SECTION + "' has no parameter '" + name + "'";
    }
    return valueText.equals(mapName.get()) ? null : changeMap.apply(valueText);
  }
}
