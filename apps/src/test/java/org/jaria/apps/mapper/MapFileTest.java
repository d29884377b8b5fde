package org.jaria.apps.mapper;

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
import org.jaria.apps.fx.TestFiles;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapFormatException;
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
        MapEdits.replace("Rename", lobby.id(), MapGeometry.renamed(lobby.object(), "Front door")));
    d.execute(MapEdits.delete(Set.of(goal1.id()), new BitSet()));
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
    d.execute(MapEdits.addObject(ArMapObject.goal("New", 1000, 1000)));
    save(d, file);
    long newId = d.content().objects().get(d.content().objects().size() - 1).id();
    d.execute(MapEdits.move(Set.of(newId), new BitSet(), 500, 0));
    save(d, file);
    ArMap m = ArMap.readFile(file);
    assertEquals(1500, m.findMapObject("New").orElseThrow().pose().x());
    assertEquals(26, m.getMapObjects().size());
  }

  @Test
  void editedLinesAndPointsAreRegenerated() throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    MapDocument d = open(file);
    d.execute(MapEdits.addLine(new ArLineSegment(0, 0, 1234, 0)));
    BitSet firstTen = new BitSet();
    firstTen.set(0, 10);
    d.execute(MapEdits.delete(Set.of(), firstTen));
    save(d, file);
    ArMap m = ArMap.readFile(file);
    assertEquals(471, m.getLines().size());
    assertEquals(63301, m.getPoints().size());
    assertEquals(new ArLineSegment(0, 0, 1234, 0), m.getLines().get(470));
  }

  @Test
  void newMapIsSavedAndReadBack() throws Exception {
    MapDocument d = MapDocument.newMap();
    d.execute(MapEdits.addLine(new ArLineSegment(0, 0, 5000, 0)));
    d.execute(MapEdits.addObject(ArMapObject.robotHome("", 100, 100, 0)));
    d.execute(MapEdits.addObject(ArMapObject.forbiddenArea(1000, 1000, 800, 400, 30)));
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

  /** A 2D-Map-Ex4 file with the header lines newer tools write, some of them odd. */
  static final String EX4 =
      """
      2D-Map-Ex4
      Sources: DATA
      DATA_Type: PointData
      MinPos: -1000 -1000
      MaxPos: 9000 6000
      NumPoints: 4
      PointsAreSorted: true
      Resolution: 20
      LineMinPos: 0 0
      LineMaxPos: 8000 5000
      NumLines: 3
      LinesAreSorted: false
      Display: "Goals" 1 "#00FF00"
      OriginLatLongAlt: 40.4168 -3.7038 650
      MapInfo: GoalType Name=Goal "Label=Goal" "Desc=A place to go" Shape=Plain
      MapInfo: SectorType Name=RedBall Sim.Color=0xD02020 Sim.Shape=cylinder Sim.Diameter=200
      MapInfo: ArgDesc Name=Speed Type=int Min=0 Max=1000
      TaskInfo: "Charge" Type=Dock
      RouteInfo: Route "Patrol" Goal1 Goal2
      SchedTaskInfo: Daily 08:00 "Patrol"
      MacroInfo: Macro "Beep" Sound=beep.wav
      CustomInfo: anything at all here
      CairnInfo: Goal1 Speed=300
      MetaInfo: Editor=Mapper3 Version=2.0
      Cairn: RobotHome 500 500 90.000000 "" ICON ""
      Cairn: Goal 2000 3000 0.000000 "" ICON "Goal1"
      Cairn: GoalWithHeading 6000 3000 -45.500000 "At the window" ICON "Goal2"
      Cairn: Dock 7500 500 180.000000 "" ICON "Dock"
      Cairn: ForbiddenLine 4000 0 0.000000 "" ICON "" 4000 0 4000 2000
      Cairn: ForbiddenArea 3000 4000 30.000000 "" ICON "" 2500 1000 3500 2000
      _Cairn: Goal 100 100 0.000000 "" ICON "Switched off"
      Cairn: RedBall 5000 4000 0.000000 "" ICON "ball"
      an unknown line the editor must keep
      LINES
      0 0 8000 0
      8000 0 8000 5000
      0 5000 8000 5000
      DATA
      -1000 -1000
      0 6000
      4000 2500
      9000 6000
      """;

  @Test
  void everyRealMapAndEveryMapTypeIsWrittenBackByteForByte() throws Exception {
    List<Path> files = new ArrayList<>();
    files.add(TestFiles.columbiaCopy(dir));
    files.add(TestFiles.referenceMapCopy(dir, "triangle.map"));
    for (String bundled : ArMap.BUNDLED_MAPS) {
      try (var in = ArMap.class.getResourceAsStream(ArMap.RESOURCE_DIR + bundled + ".map")) {
        Path f = dir.resolve("bundled-" + bundled + ".map");
        Files.copy(in, f);
        files.add(f);
      }
    }
    for (String type : List.of("2D-Map-Ex", "2D-Map-Ex2", "2D-Map-Ex3", "2D-Map-Ex4")) {
      Path f = dir.resolve(type + ".map");
      Files.writeString(f, EX4.replace("2D-Map-Ex4", type).replace("\n", "\r\n"));
      files.add(f);
    }
    for (Path f : files) {
      MapDocument d = open(f);
      Path out = dir.resolve("out-" + f.getFileName());
      save(d, out);
      assertArrayEquals(Files.readAllBytes(f), Files.readAllBytes(out), f::toString);
      assertEquals(ArMap.readFile(f), ArMap.readFile(out), f::toString);
    }
  }

  @Test
  void editingAnEx4MapKeepsEveryLineItDoesNotUnderstand() throws Exception {
    Path f = dir.resolve("ex4.map");
    Files.writeString(f, EX4);
    MapDocument d = open(f);
    assertEquals("2D-Map-Ex4", d.file().mapType());
    assertEquals(7, d.content().objects().size(), "inactive _Cairn lines are not objects");
    MapObjectEntry area =
        d.content().objects().stream()
            .filter(e -> e.object().isAreaType())
            .findFirst()
            .orElseThrow();
    d.execute(MapEdits.replace("Rotate", area.id(), MapGeometry.withHeading(area.object(), 75)));
    d.execute(MapEdits.addObject(ArMapObject.goal("Goal3", 1000, 4000)));
    save(d, f);
    List<String> before = EX4.lines().toList();
    List<String> after = Files.readAllLines(f);
    for (String line : before) {
      if (!line.startsWith("Cairn: ForbiddenArea")) {
        assertTrue(after.contains(line), () -> "lost: " + line);
      }
    }
    assertEquals(before.size() + 1, after.size());
    ArMap m = ArMap.readFile(f);
    assertEquals(75, m.findFirstMapObjectOfType("ForbiddenArea").orElseThrow().pose().th(), 1e-9);
    assertTrue(m.findMapObject("Goal3").isPresent());
  }
}
