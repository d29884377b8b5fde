package org.jaria.tools.mapper;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapFormatException;
import org.jaria.tools.fx.TestFiles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Saving touches only what was edited; everything else in a real map survives byte for byte. */
class MapFileTest {

  @TempDir Path dir;

  private MapDocument open(Path file) throws Exception {
    AtomicLong ids = new AtomicLong(1);
    return new MapDocument(MapFile.read(file, ids::getAndIncrement), file, ids);
  }

  private static void save(MapDocument d, Path to) throws Exception {
    d.file().save(d.content(), to);
    d.markSaved(d.saveMark(), to);
  }

  @Test
  void uneditedColumbiaIsWrittenBackByteForByte() throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    MapDocument d = open(file);
    Path out = dir.resolve("out.map");
    save(d, out);
    assertArrayEquals(Files.readAllBytes(file), Files.readAllBytes(out));
  }

  @Test
  void renameDeleteAndMoveChangeOnlyTheirLines() throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    List<String> before = Files.readAllLines(file, StandardCharsets.UTF_8);
    MapDocument d = open(file);
    MapObjectEntry lobby =
        d.content().objects().stream()
            .filter(e -> e.object().name().equals("Lobby door"))
            .findFirst()
            .orElseThrow();
    MapObjectEntry goal1 =
        d.content().objects().stream()
            .filter(e -> e.object().name().equals("Goal 1"))
            .findFirst()
            .orElseThrow();
    d.execute(
        MapCommands.replace(
            "Rename", lobby.id(), MapGeometry.renamed(lobby.object(), "Front door")));
    d.execute(MapCommands.delete(Set.of(goal1.id()), new BitSet()));
    save(d, file);

    List<String> after = Files.readAllLines(file, StandardCharsets.UTF_8);
    assertEquals(before.size() - 1, after.size());
    List<String> expected = new ArrayList<>(before);
    int i = expected.indexOf(lobby.object().toMapLine());
    expected.set(i, MapGeometry.renamed(lobby.object(), "Front door").toMapLine());
    expected.remove(goal1.object().toMapLine());
    assertEquals(expected, after);
    assertTrue(ArMap.readFile(file).findMapObject("Front door").isPresent());
    assertFalse(ArMap.readFile(file).findMapObject("Goal 1").isPresent());
  }

  @Test
  void secondSaveAfterMoreEditsStillTouchesOnlyThose() throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    MapDocument d = open(file);
    d.execute(MapCommands.addObject(ArMapObject.goal("New", 1000, 1000)));
    save(d, file);
    long newId = d.content().objects().get(d.content().objects().size() - 1).id();
    d.execute(MapCommands.move(Set.of(newId), new BitSet(), 500, 0));
    save(d, file);
    ArMap m = ArMap.readFile(file);
    assertEquals(1500, m.findMapObject("New").orElseThrow().pose().x());
    assertEquals(26, m.getMapObjects().size());
  }

  @Test
  void editedLinesAndPointsAreRegenerated() throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    MapDocument d = open(file);
    d.execute(MapCommands.addLine(new ArLineSegment(0, 0, 1234, 0)));
    BitSet firstTen = new BitSet();
    firstTen.set(0, 10);
    d.execute(MapCommands.delete(Set.of(), firstTen));
    save(d, file);
    ArMap m = ArMap.readFile(file);
    assertEquals(471, m.getLines().size());
    assertEquals(63301, m.getPoints().size());
    assertEquals(new ArLineSegment(0, 0, 1234, 0), m.getLines().get(470));
  }

  @Test
  void newMapIsSavedAndReadBack() throws Exception {
    MapDocument d = MapDocument.newMap();
    d.execute(MapCommands.addLine(new ArLineSegment(0, 0, 5000, 0)));
    d.execute(MapCommands.addObject(ArMapObject.robotHome("", 100, 100, 0)));
    d.execute(MapCommands.addObject(ArMapObject.forbiddenArea(1000, 1000, 800, 400, 30)));
    Path out = dir.resolve("new.map");
    save(d, out);
    ArMap m = ArMap.readFile(out);
    assertEquals(d.content().segments(), m.getLines());
    assertEquals(d.content().mapObjects(), m.getMapObjects());
  }

  @Test
  void failedSaveLeavesTheFileAlone() throws Exception {
    MapDocument d = MapDocument.newMap();
    Path missing = dir.resolve("no-such-folder").resolve("x.map");
    assertThrows(IOException.class, () -> d.file().save(d.content(), missing));
    assertFalse(Files.exists(missing));
  }

  @Test
  void garbageFileNamesLine() throws Exception {
    Path bad = dir.resolve("bad.map");
    Files.writeString(bad, "2D-Map\nLINES\n1 2 three 4\n");
    MapFormatException e = assertThrows(MapFormatException.class, () -> open(bad));
    assertEquals(3, e.getLine());
    assertTrue(MapperWindow.openError(bad, e).contains("bad.map:3"));
  }
}
