package org.jaria.arnl;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigException;

/**
 * The typical parameter file of the localization and path-planning tasks (ARNL's {@code
 * params/arnl.p}), bundled as a resource: both sections with every parameter at its default value
 * and a comment saying what it does. Copy it next to your program, edit it, and load it with {@link
 * ArConfig#parseFile}.
 */
public final class Arnl {

  /** Classpath resource holding the typical parameter file. */
  public static final String TYPICAL_PARAM_RESOURCE = "/org/jaria/arnl/arnl.p";

  private Arnl() {}

  /** The text of the typical parameter file. */
  public static String typicalParamFileText() {
    try (InputStream in = Arnl.class.getResourceAsStream(TYPICAL_PARAM_RESOURCE)) {
      if (in == null) {
        throw new IllegalStateException(
            TYPICAL_PARAM_RESOURCE
                + " is missing from the classpath: the arnl-sonar jar is broken");
      }
      return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  /** Loads the typical parameter file into {@code config}. */
  public static ArConfig.ParseResult loadTypicalParams(ArConfig config) throws ArConfigException {
    return config.parseText(typicalParamFileText(), "arnl.p");
  }
}
