package org.jaria.params;

import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;
import java.util.List;

/** The real ARIA parameter files copied into the test resources. */
final class ReferenceParams {

  /** Subtypes with a real file in src/test/resources/reference/params. */
  static final List<String> SUBTYPES = List.of("p3dx-sh", "p3at-sh", "p3dx", "p3at");

  private ReferenceParams() {}

  static Path path(String subtype) {
    URL url = ReferenceParams.class.getResource("/reference/params/" + subtype + ".p");
    if (url == null) {
      throw new IllegalStateException("missing test resource for " + subtype);
    }
    try {
      return Path.of(url.toURI());
    } catch (URISyntaxException e) {
      throw new IllegalStateException(e);
    }
  }
}
