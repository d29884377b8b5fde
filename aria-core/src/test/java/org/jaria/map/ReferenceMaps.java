package org.jaria.map;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;

/** The real maps copied into the test resources, and small helpers for map tests. */
final class ReferenceMaps {

  private ReferenceMaps() {}

  static Path path(String name) {
    URL url = ReferenceMaps.class.getResource("/reference/maps/" + name);
    if (url == null) {
      throw new IllegalStateException("missing test resource " + name);
    }
    try {
      return Path.of(url.toURI());
    } catch (URISyntaxException e) {
      throw new IllegalStateException(e);
    }
  }

  static String write(ArMap m) {
    StringWriter w = new StringWriter();
    try {
      m.write(w);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    return w.toString();
  }

  static ArMap parse(String text) throws MapFormatException {
    return parseAs(text, "test.map");
  }

  static ArMap parseAs(String text, String source) throws MapFormatException {
    try {
      return ArMap.read(new StringReader(text), source);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }
}
