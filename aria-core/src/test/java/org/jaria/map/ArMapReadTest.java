package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

class ArMapReadTest {

  @Test
  void columbiaMap() throws Exception {
    ArMap m = ArMap.readFile(ReferenceMaps.path("columbia.map"));
    assertEquals("2D-Map", m.getMapType());
    assertEquals(470, m.getLines().size());
    assertEquals(63311, m.getPoints().size());
    assertEquals(new ArLineSegment(-4756, 7542, -4756, 3523), m.getLines().get(0));
    assertEquals(19560, m.getPoints().x(63310));
    assertEquals(-9360, m.getPoints().y(63310));
    assertTrue(m.getPoints().isSorted());
    assertEquals(20, m.getResolution());
    assertEquals(new ArPose(-4780, -27000), m.getMinPos());
    assertEquals(new ArPose(19560, 24680), m.getMaxPos());
    assertEquals(new ArPose(-4756, -26950), m.getLineMinPos());
    assertEquals(new ArPose(19533, 19394), m.getLineMaxPos());

    assertEquals(25, m.getMapObjects().size());
    assertEquals(10, m.getGoals().size());
    assertEquals(Optional.of(new ArPose(-182, 176, 0)), m.findHomePose());
    ArMapObject lobby = m.findMapObject("LOBBY DOOR").orElseThrow();
    assertEquals("GoalWithHeading", lobby.type());
    assertEquals(-48.5763, lobby.pose().th(), 1e-12);
    assertEquals("ICON", lobby.iconName());
    assertEquals("", lobby.description());

    ArMapObject area = m.findFirstMapObjectOfType("forbiddenarea").orElseThrow();
    assertTrue(area.hasFromTo());
    assertEquals(new ArPose(-4540, -10800), area.fromPose());
    ArMapObject inside = m.findMapObject("Inside Forbidden Area").orElseThrow();
    assertTrue(area.contains(inside.pose().x(), inside.pose().y()));
    ArMapObject impossible = m.findMapObject("Impossible Goal").orElseThrow();
    assertFalse(area.contains(impossible.pose().x(), impossible.pose().y()));

    List<MapInfoEntry> info = m.getMapInfo();
    assertEquals(4, info.size());
    assertEquals("BoundaryType", info.get(1).typeClass());
    assertEquals("Measure", info.get(1).getName());
    assertEquals("Measuring stick", info.get(1).attributes().get("Label"));
    assertEquals("Line that displays its length", info.get(1).attributes().get("Desc"));
    assertEquals("18", info.get(3).attributes().get("FtSize"));
    assertEquals(
        List.of("OriginLatLongAlt: 42.807191 -71.578661 72.000000"), m.getOtherHeaderLines());
  }

  @Test
  void triangleMapHasLinesButNoPoints() throws Exception {
    ArMap m = ArMap.readFile(ReferenceMaps.path("triangle.map"));
    assertEquals(9, m.getLines().size());
    assertTrue(m.getPoints().isEmpty());
    assertEquals(-1, m.getResolution());
    assertEquals(Optional.of(new ArPose(5090, 3580, 54)), m.findHomePose());
    assertEquals(new ArPose(0, 0), m.getMinPos(), "falls back to the lines without points");
    assertEquals(new ArPose(10260, 10080), m.getMaxPos());
    assertTrue(m.getGoals().isEmpty());
    assertEquals("Home", m.getMapObjects().get(0).name());
  }

  @Test
  void homeFallsBackToDockThenNothing() throws Exception {
    ArMap dockOnly =
        ReferenceMaps.parse("2D-Map\nCairn: Dock 100 200 90.5 \"\" ICON \"Charger\"\nDATA\n");
    assertEquals(Optional.of(new ArPose(100, 200, 90.5)), dockOnly.findHomePose());
    assertEquals(Optional.empty(), ReferenceMaps.parse("2D-Map\n").findHomePose());
  }

  @Test
  void tolerantInputIsAccepted() throws Exception {
    String text =
        String.join(
            "\r\n",
            "2D-Map-Ex4",
            "Sources: SickLaser",
            "",
            "_Cairn: Goal 1 2 0 \"\" ICON \"inactive\"",
            "Cairn: Goal 1.5 -2.25 370 \"desc\" ICON \"A\" \"trailing description\"   ",
            "LINES",
            "0\t0   10 10  ",
            "",
            "DATA",
            "1 2",
            "3.6 -4.4",
            "");
    ArMap m = ReferenceMaps.parse(text);
    assertEquals("2D-Map-Ex4", m.getMapType());
    assertEquals(List.of(new ArLineSegment(0, 0, 10, 10)), m.getLines());
    assertEquals(2, m.getPoints().size());
    assertEquals(4, m.getPoints().x(1), "decimals are rounded to whole mm");
    assertEquals(-4, m.getPoints().y(1));
    ArMapObject a = m.findMapObject("a").orElseThrow();
    assertEquals(new ArPose(1.5, -2.25, 10), a.pose());
    assertEquals("trailing description", a.description());
    assertEquals(1, m.getMapObjects().size(), "_Cairn objects are inactive");
    assertEquals(
        List.of("Sources: SickLaser", "", "_Cairn: Goal 1 2 0 \"\" ICON \"inactive\""),
        m.getOtherHeaderLines());
    assertEquals(text, ReferenceMaps.write(m), "and written back unchanged");
  }

  @Test
  void headerCountsAndBoundsAreNotTrusted() throws Exception {
    ArMap m =
        ReferenceMaps.parse(
            """
            2D-Map
            MinPos: 0 0
            MaxPos: 1 1
            NumPoints: 900000000
            NumLines: 7
            LINES
            -5 -5 5 5
            DATA
            100 -200
            -300 400
            """);
    assertEquals(2, m.getPoints().size());
    assertEquals(1, m.getLines().size());
    assertEquals(new ArPose(-300, -200), m.getMinPos());
    assertEquals(new ArPose(100, 400), m.getMaxPos());
    assertEquals(new ArPose(-5, -5), m.getLineMinPos());
  }
}
