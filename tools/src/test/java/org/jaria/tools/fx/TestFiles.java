package org.jaria.tools.fx;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/** Reference files for the desktop apps' tests. */
public final class TestFiles {

  private TestFiles() {}

  /**
   * A fresh copy of the real 63k-point columbia.map in {@code dir} (from aria-core's test
   * resources: the source folder when run from the tools module, else the class path).
   */
  public static Path columbiaCopy(Path dir) throws IOException {
    Path target = dir.resolve("columbia.map");
    Path src = Path.of("../aria-core/src/test/resources/reference/maps/columbia.map");
    if (Files.isRegularFile(src)) {
      return Files.copy(src, target, StandardCopyOption.REPLACE_EXISTING);
    }
    try (InputStream in = TestFiles.class.getResourceAsStream("/reference/maps/columbia.map")) {
      if (in == null) {
        throw new IOException(
            "columbia.map is neither in aria-core's sources nor on the class path");
      }
      Files.copy(in, target, StandardCopyOption.REPLACE_EXISTING);
    }
    return target;
  }
}
