package org.jaria.tools;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;

/** JAria's version, as the build wrote it into {@code org/jaria/tools/version.properties}. */
public final class ProjectVersion {

  private ProjectVersion() {}

  /** The project version, e.g. {@code 0.1.0-SNAPSHOT}, or {@code unknown} outside a build. */
  public static String get() {
    Properties p = new Properties();
    try (InputStream in =
        ProjectVersion.class.getResourceAsStream("/org/jaria/tools/version.properties")) {
      if (in != null) {
        p.load(in);
      }
    } catch (IOException e) {
      // fall through to "unknown"
    }
    return p.getProperty("version", "unknown");
  }
}
