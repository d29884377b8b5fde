package org.jaria.site;

import java.nio.file.Files;
import java.nio.file.Path;

/** The repository root, seen from the site module's tests (which run in site/). */
final class Repo {

  private Repo() {}

  static Path root() {
    Path here = Path.of("").toAbsolutePath();
    for (Path p = here; p != null; p = p.getParent()) {
      if (Files.isRegularFile(p.resolve("mvnw")) && Files.isDirectory(p.resolve("docs"))) {
        return p;
      }
    }
    throw new IllegalStateException("not inside the JAria repository: " + here);
  }
}
