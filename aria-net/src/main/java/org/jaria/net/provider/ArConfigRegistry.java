package org.jaria.net.provider;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigArg;
import org.jaria.config.ArConfigSection;
import org.jaria.net.data.ConfigParam;
import org.jaria.net.data.ConfigSection;

/**
 * Serves an {@link ArConfig} (the robot program's typed parameters) to monitors: every section with
 * its parameters as text, and setting one parameter from text with the same checks as a {@code .p}
 * file. After a parameter changes, the config's process-file callbacks run, as after loading a
 * file, so modules pick up the new value.
 */
public final class ArConfigRegistry implements ConfigRegistry {

  private final ArConfig config;

  /** Serves {@code config}. */
  public ArConfigRegistry(ArConfig config) {
    this.config = Objects.requireNonNull(config, "config");
  }

  @Override
  public List<ConfigSection> getSections() {
    List<ConfigSection> out = new ArrayList<>();
    for (ArConfigSection s : config.getSections()) {
      List<ConfigParam> params = new ArrayList<>();
      for (ArConfigArg a : s.getParams()) {
        params.add(
            new ConfigParam(
                a.getName(),
                a.getType().name(),
                a.getValueText(),
                a.getDefaultText(),
                a.hasMin() ? number(a, a.getMin()) : "",
                a.hasMax() ? number(a, a.getMax()) : "",
                a.getDescription()));
      }
      out.add(new ConfigSection(s.getName(), s.getComment(), params));
    }
    return out;
  }

  private static String number(ArConfigArg a, double v) {
    return a.getType() == ArConfigArg.Type.INT
        ? Long.toString((long) v)
        : String.format(Locale.ROOT, "%s", v);
  }

  @Override
  public String setParam(String section, String name, String valueText) {
    Optional<ArConfigArg> arg = config.findParam(section, name);
    if (arg.isEmpty()) {
      return config.findSection(section).isEmpty()
          ? "no configuration section '" + section + "'"
          : "section '" + section + "' has no parameter '" + name + "'";
    }
    ArConfigArg a = arg.get();
    String old = a.getValueText();
    try {
      if (!a.setValueFromText(valueText)) {
        return null;
      }
    } catch (IllegalArgumentException e) {
      return e.getMessage();
    }
    if (!config.callProcessFileCallBacks()) {
      a.setValueFromText(old);
      config.callProcessFileCallBacks();
      return name + ": the program refused the value " + valueText + "; it stays " + old;
    }
    return null;
  }

  @Override
  public String toString() {
    return "ArConfigRegistry[" + config.getSections().size() + " sections]";
  }
}
