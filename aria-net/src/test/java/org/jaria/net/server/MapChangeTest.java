package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.jaria.map.ArMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * ARIA's {@code Files/Map} parameter: a client that sets it (as {@code changeMapOnServer} does)
 * changes the map the server navigates on and serves; names that lead outside the map folder are
 * refused before anything is read.
 */
class MapChangeTest {

  @Test
  void namesOutsideTheMapFolderAreRefusedWithTheRule(@TempDir Path dir) throws Exception {
    Path maps = Files.createDirectories(dir.resolve("maps"));
    Files.writeString(dir.resolve("secret.map"), "2D-Map\nDATA\n");
    Files.writeString(maps.resolve("broken.map"), "not a map\n");
    Files.createSymbolicLink(maps.resolve("link.map"), dir.resolve("secret.map"));
    Files.createDirectories(maps.resolve("folder.map"));
    ArMap.loadBundled("hall").writeFile(maps.resolve("mine.map"));
    MapFolder f = new MapFolder(maps);
    assertEquals(ArMap.loadBundled("hall").getLines().size(), f.load("mine.map").getLines().size());
    assertEquals(ArMap.loadBundled("office").getLines().size(), f.load("office").getLines().size());
    String[][] refused = {
      {"../secret.map", "inside the server's map folder"},
      {dir.resolve("secret.map").toString(), "relative to the server's map folder"},
      {"link.map", "inside the server's map folder"},
      {"folder.map", "is not a file"},
      {"", "give the name of a map file"},
      {"x".repeat(300), "not a map file name"},
      {"nothing.map", "no map 'nothing.map'"}
    };
    for (String[] r : refused) {
      IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> f.load(r[0]));
      assertTrue(e.getMessage().contains(r[1]), r[0] + ": " + e.getMessage());
    }
    assertThrows(org.jaria.map.MapFormatException.class, () -> f.load("broken.map"));
    MapFolder bundledOnly = new MapFolder(null);
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> bundledOnly.load("mine.map"));
    assertTrue(e.getMessage().contains("only its bundled maps"), e.getMessage());
  }
}
