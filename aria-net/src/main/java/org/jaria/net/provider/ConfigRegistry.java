package org.jaria.net.provider;

import java.util.List;
import org.jaria.net.data.ConfigSection;

/**
 * The robot program's configuration as the network server sees it (an adapter over {@code
 * org.jaria.config.ArConfig}): read every section, set one parameter from text. Methods are called
 * from the server's worker threads and must be thread-safe.
 */
public interface ConfigRegistry {

  /** Every section with its parameters, as they are now. */
  List<ConfigSection> getSections();

  /**
   * Sets a parameter from text (as in a {@code .p} file).
   *
   * @return null if it was set, otherwise a message saying why not ("NumSamples: 5 is below the
   *     minimum 10")
   */
  String setParam(String section, String name, String valueText);
}
