package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What {@code jaria mapper NAME} opens: a file if there is one, else a bundled map. */
class MapSourceTest {

  @Test
  void theReadmesNameOpensTheBundledColumbiaMap() {
    assertEquals(new MapSource(null, "columbia"), MapSource.resolve("columbia"));
    assertEquals(new MapSource(null, "columbia"), MapSource.resolve("columbia.map"));
    assertEquals(new MapSource(null, "office"), MapSource.resolve("office"));
  }

  @Test
  void anExistingFileWins(@TempDir Path dir) throws IOException {
    Path f = Files.writeString(dir.resolve("hall"), "2D-Map\nDATA\n");
    MapSource s = MapSource.resolve(f.toString());
    assertEquals(f, s.file());
    assertNull(s.bundledName());
  }

  @Test
  void neitherFileNorBundledMapSaysWhatExists(@TempDir Path dir) {
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class,
            () -> MapSource.resolve(dir.resolve("nowhere.map").toString()));
    assertTrue(e.getMessage().contains("no map file"), e.getMessage());
    assertTrue(e.getMessage().contains("bundled: office, hall, columbia"), e.getMessage());
  }
}
