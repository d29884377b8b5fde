package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

class ArMapObjectTest {

  private static ArMapObject parse(String line) throws MapFormatException {
    return ReferenceMaps.parse("2D-Map\n" + line + "\n").getMapObjects().get(0);
  }

  private static void assertSegment(ArLineSegment s, double x1, double y1, double x2, double y2) {
    assertEquals(x1, s.x1(), 1e-9);
    assertEquals(y1, s.y1(), 1e-9);
    assertEquals(x2, s.x2(), 1e-9);
    assertEquals(y2, s.y2(), 1e-9);
  }

  @Test
  void unrotatedAreaWithAbsoluteCorners() throws Exception {
    ArMapObject a =
        parse("Cairn: ForbiddenArea 0 0 0.000000 \"\" ICON \"\" 280 -14900 3900 -13000");
    assertTrue(a.isAreaType());
    List<ArLineSegment> s = a.getFromToSegments();
    assertEquals(4, s.size());
    assertSegment(s.get(0), 280, -14900, 3900, -14900);
    assertSegment(s.get(1), 3900, -14900, 3900, -13000);
    assertSegment(s.get(2), 3900, -13000, 280, -13000);
    assertSegment(s.get(3), 280, -13000, 280, -14900);
    assertTrue(a.contains(280, -14900), "edges belong to the area");
    assertTrue(a.contains(2000, -14000));
    assertFalse(a.contains(2000, -12999));
  }

  @Test
  void rotatedAreaTurnsAboutTheMapOriginAndIgnoresPoseXy() throws Exception {
    // As ARIA's ArMapObject: corners (x1,y1)-(x2,y2) rotated by th about (0,0).
    ArMapObject a =
        parse("Cairn: ForbiddenArea 5000 7000 90.000000 \"\" ICON \"\" 1000 0 2000 500");
    List<ArLineSegment> s = a.getFromToSegments();
    assertSegment(s.get(0), 0, 1000, 0, 2000);
    assertSegment(s.get(1), 0, 2000, -500, 2000);
    assertSegment(s.get(2), -500, 2000, -500, 1000);
    assertSegment(s.get(3), -500, 1000, 0, 1000);
    assertTrue(a.contains(-250, 1500));
    assertFalse(a.contains(1500, 250), "the unrotated box is not the area");
    assertFalse(a.contains(5000, 7000), "the pose is not where the area is");
    ArMapObject moved = parse("Cairn: ForbiddenArea 0 0 90.000000 \"\" ICON \"\" 1000 0 2000 500");
    assertEquals(a.getFromToSegments(), moved.getFromToSegments());
  }

  @Test
  void areaFromCentreSizeAndAngle() {
    ArMapObject a = ArMapObject.forbiddenArea(3000, 1000, 2000, 400, 30);
    assertEquals(new ArPose(3000, 1000, 30), a.pose());
    assertTrue(a.contains(3000, 1000));
    double r = Math.toRadians(30);
    // Just inside and just outside the long axis end.
    assertTrue(a.contains(3000 + 990 * Math.cos(r), 1000 + 990 * Math.sin(r)));
    assertFalse(a.contains(3000 + 1010 * Math.cos(r), 1000 + 1010 * Math.sin(r)));
    // Short axis: half height is 200.
    assertTrue(a.contains(3000 - 190 * Math.sin(r), 1000 + 190 * Math.cos(r)));
    assertFalse(a.contains(3000 - 210 * Math.sin(r), 1000 + 210 * Math.cos(r)));
    double perimeter = a.getFromToSegments().stream().mapToDouble(ArLineSegment::length).sum();
    assertEquals(4800, perimeter, 1e-6);
  }

  @Test
  void forbiddenLineIsOneUnrotatedSegment() throws Exception {
    ArMapObject l = parse("Cairn: ForbiddenLine 540 19340 45.0 \"\" ICON \"\" 540 19340 540 9020");
    assertTrue(l.isLineType());
    assertEquals(List.of(new ArLineSegment(540, 19340, 540, 9020)), l.getFromToSegments());
    assertFalse(l.contains(540, 10000));
    assertEquals(new ArLineSegment(540, 19340, 540, 9020), l.getFromToSegment());
  }

  @Test
  void pointObjects() {
    ArMapObject g = ArMapObject.goal("Kitchen", 10, 20);
    assertTrue(g.isGoal());
    assertFalse(g.hasFromTo());
    assertNull(g.fromPose());
    assertTrue(g.getFromToSegments().isEmpty());
    assertNull(g.getFromToSegment());
    assertFalse(g.contains(10, 20));
    assertFalse(ArMapObject.robotHome("", 0, 0, 0).isGoal());
    assertEquals("Cairn: Goal 10 20 0.000000 \"\" ICON \"Kitchen\"", g.toMapLine());
  }

  @Test
  void objectsThatCannotBeWrittenAreRefused() {
    assertThrows(IllegalArgumentException.class, () -> ArMapObject.goal("say \"hi\"", 0, 0));
    assertThrows(IllegalArgumentException.class, () -> ArMapObject.goal("two\nlines", 0, 0));
    assertThrows(
        IllegalArgumentException.class, () -> new ArMapObject("Two Words", ArPose.ORIGIN, "", ""));
    assertThrows(IllegalArgumentException.class, () -> ArMapObject.goal("nan", Double.NaN, 0));
    assertThrows(
        IllegalArgumentException.class,
        () -> new ArMapObject("ForbiddenLine", ArPose.ORIGIN, "", "ICON", "", true, null, null));
  }
}
