package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigSection;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * ARIA's {@code Files/Map} parameter: a client that sets it (as {@code changeMapOnServer} does)
 * changes the map the server navigates on and serves; names that lead outside the map folder are
 * refused before anything is read.
 */
class MapChangeTest {

  @Test
  void settingFilesMapChangesTheMapForNavigationAndClients() throws Exception {
    try (GuiRig rig = GuiRig.arnl();
        ArClientBase watcher = new ArClientBase("watcher")) {
      watcher.connect("127.0.0.1", rig.gui.getServer().getPort(), "", "");
      AtomicInteger updated = new AtomicInteger();
      watcher.addHandler("mapUpdated", p -> updated.incrementAndGet());
      Futures.get(watcher.request("mapUpdated", -1));
      List<ConfigSection> sections = ConfigLayout.readAll(rig.call("getConfigBySections"));
      ConfigSection files = sections.get(0);
      assertEquals("Files", files.name(), "ARIA's section, first");
      assertEquals("Map", files.params().get(0).name());
      assertEquals("office.map", files.params().get(0).value());
      assertEquals("", rig.call("setConfig", "Section", "Files", "Map", "hall").bufToStr());
      assertEquals("hall", rig.call("getMapName").bufToStr());
      assertEquals(
          ArMap.loadBundled("hall").getLines().size(),
          rig.nav.getPathPlanningTask().getAriaMap().getLines().size(),
          "the planner plans on the new map");
      assertEquals(
          ArMap.loadBundled("hall").getGoals().stream().map(o -> o.name()).toList(),
          GuiRig.stringsToEnd(rig.call("getGoals")));
      Eventually.until("mapUpdated reached the other client", () -> updated.get() == 1);
      assertEquals("Stop", rig.gui.getModes().getMode(), "the robot was stopped first");
      ConfigSection after = ConfigLayout.readAll(rig.call("getConfigBySections")).get(0);
      assertEquals("hall", after.params().get(0).value());
    }
  }

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

  @Test
  void aClientAskingForAMapOutsideTheFolderIsAnsweredWithTheRefusal() throws Exception {
    try (GuiRig rig = GuiRig.arnl()) {
      ArNetPacket answer = rig.call("setConfig", "Section", "Files", "Map", "../../etc/passwd");
      String why = answer.bufToStr();
      assertTrue(why.startsWith("Map: "), why);
      assertEquals("office.map", rig.call("getMapName").bufToStr(), "the map stayed");
    }
  }
}
