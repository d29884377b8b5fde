package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

class ArMapEditTest {

  @Test
  void objectEditsWriteAndReloadEqual() throws Exception {
    ArMap m = ArMap.readFile(ReferenceMaps.path("columbia.map"));
    String before = ReferenceMaps.write(m);
    ArMapObject g1 = m.findMapObject("Goal 1").orElseThrow();
    assertTrue(m.removeMapObject(g1));
    assertFalse(m.removeMapObject(g1));
    ArMapObject moved = ArMapObject.goalWithHeading("Workshop", 13000.5, -12200, 33.3333333333);
    assertTrue(m.replaceMapObject(m.findMapObject("Workshop").orElseThrow(), moved));
    m.addMapObject(ArMapObject.goal("Coffee", 100, 200));
    m.addMapObject(ArMapObject.forbiddenArea(1000, 1000, 400, 200, 30));
    m.addMapObject(ArMapObject.forbiddenLine(0, 0, 10, 10));

    String after = ReferenceMaps.write(m);
    ArMap reloaded = ReferenceMaps.parse(after);
    assertEquals(m, reloaded);
    assertEquals(m.getMapObjects(), reloaded.getMapObjects());
    assertEquals(moved, reloaded.findMapObject("workshop").orElseThrow());
    assertTrue(reloaded.findMapObject("Goal 1").isEmpty());
    assertEquals("Coffee", reloaded.getMapObjects().get(24).name());

    // Only the touched lines changed: same body, same other header lines.
    assertEquals(
        before.substring(before.indexOf("\nLINES\n")), after.substring(after.indexOf("\nLINES\n")));
    assertTrue(
        after.contains(
            "\nCairn: GoalWithHeading 13000.5 -12200 33.3333333333 \"\" ICON \"Workshop\"\n"));
    assertTrue(after.contains("\nCairn: Goal 100 200 0.000000 \"\" ICON \"Coffee\"\n"));
    assertFalse(after.contains("\"Goal 1\""));
  }

  @Test
  void lineAndPointEditsRegenerateSectionsAndHeaderCounts() throws Exception {
    ArMap m = ArMap.readFile(ReferenceMaps.path("columbia.map"));
    List<ArLineSegment> lines = new ArrayList<>(m.getLines().subList(0, 10));
    m.setLines(lines);
    m.addLine(new ArLineSegment(-6000, 0, 0, 30000.5));
    m.setPoints(ArMapPoints.of(new int[] {5, -7, 9}, new int[] {1, 2, -3}));
    String text = ReferenceMaps.write(m);
    assertTrue(
        text.contains("\nMinPos: -7 -3\nMaxPos: 9 2\nNumPoints: 3\nPointsAreSorted: false\n"),
        text.substring(0, 300));
    assertTrue(text.contains("\nLineMinPos: -6000 -15203\n"), text.substring(0, 400));
    assertTrue(text.contains("\nLineMaxPos: 841 30000.5\nNumLines: 11\nLinesAreSorted: false\n"));
    assertTrue(text.contains("\n-6000 0 0 30000.5\nDATA\n5 1\n-7 2\n9 -3\n"));
    assertTrue(text.endsWith("9 -3\n"));
    ArMap reloaded = ReferenceMaps.parse(text);
    assertEquals(m, reloaded);
    assertEquals(11, reloaded.getLines().size());
    assertEquals(new ArPose(-7, -3), reloaded.getMinPos());
  }

  @Test
  void newMapFromScratch() throws Exception {
    ArMap m = new ArMap();
    m.addLine(new ArLineSegment(0, 0, 1000, 0));
    m.addMapObject(ArMapObject.robotHome("", 500, 500, 90));
    m.addMapObject(ArMapObject.dock("Dock", 900, 500, 0));
    String text = ReferenceMaps.write(m);
    assertEquals(
        """
        2D-Map
        MinPos: 0 0
        MaxPos: 0 0
        NumPoints: 0
        LineMinPos: 0 0
        LineMaxPos: 1000 0
        NumLines: 1
        Cairn: RobotHome 500 500 90.000000 "" ICON ""
        Cairn: Dock 900 500 0.000000 "" ICON "Dock"
        LINES
        0 0 1000 0
        DATA
        """,
        text);
    ArMap reloaded = ReferenceMaps.parse(text);
    assertEquals(m, reloaded);
    assertEquals(new ArPose(500, 500, 90), reloaded.findHomePose().orElseThrow());
  }

  @Test
  void linesAddedToAMapWithoutALinesSectionGoBeforeData() throws Exception {
    ArMap m = ReferenceMaps.parse("2D-Map\nResolution: 100\nDATA\n1 1\n");
    m.addLine(new ArLineSegment(0, 0, 5, 5));
    String text = ReferenceMaps.write(m);
    assertEquals(
        "2D-Map\nLineMinPos: 0 0\nLineMaxPos: 5 5\nNumLines: 1\nResolution: 100\nLINES\n0 0 5 5\nDATA\n1 1\n",
        text);
    assertEquals(m, ReferenceMaps.parse(text));
  }

  @Test
  void equalityNoticesDifferences() throws Exception {
    ArMap a = ArMap.readFile(ReferenceMaps.path("triangle.map"));
    ArMap b = ArMap.readFile(ReferenceMaps.path("triangle.map"));
    assertEquals(a, b);
    assertEquals(a.hashCode(), b.hashCode());
    b.addMapObject(ArMapObject.goal("x", 1, 1));
    assertNotEquals(a, b);
  }
}
