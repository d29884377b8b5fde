package org.jaria.apps.fx;

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
    return referenceMapCopy(dir, "columbia.map");
  }

  /**
   * A fresh copy of one of aria-core's reference maps (columbia.map, triangle.map) in {@code dir}.
   */
  public static Path referenceMapCopy(Path dir, String name) throws IOException {
    Path target = dir.resolve(name);
    Path src = Path.of("../aria-core/src/test/resources/reference/maps/" + name);
    if (Files.isRegularFile(src)) {
      return Files.copy(src, target, StandardCopyOption.REPLACE_EXISTING);
    }
    try (InputStream in = TestFiles.class.getResourceAsStream("/reference/maps/" + name)) {
      if (in == null) {
        throw new IOException(name + " is neither in aria-core's sources nor on the class path");
      }
      Files.copy(in, target, StandardCopyOption.REPLACE_EXISTING);
    }
    return target;
  }
}
