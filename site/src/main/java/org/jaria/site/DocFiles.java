package org.jaria.site;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** The Markdown files that make the documentation: the README and everything under docs/. */
public final class DocFiles {

  private DocFiles() {}

  /** Their paths relative to {@code root}, README first, then docs/ in name order. */
  public static List<Path> list(Path root) throws IOException {
    List<Path> out = new ArrayList<>();
    out.add(Path.of("README.md"));
    try (Stream<Path> s = Files.walk(root.resolve("docs"))) {
      s.filter(p -> p.toString().endsWith(".md")).map(root::relativize).sorted().forEach(out::add);
    }
    return out;
  }
}
