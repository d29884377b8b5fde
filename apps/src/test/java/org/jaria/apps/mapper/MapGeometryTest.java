package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

class MapGeometryTest {

  @Test
  void mapper3StyleAreaMovesItsCornersAndKeepsPoseAtOrigin() {
    ArMapObject a = ArMapObject.forbiddenArea(0, 0, 100, 50);
    ArMapObject m = MapGeometry.translate(a, 10, 20);
    assertEquals(ArMapObject.forbiddenArea(10, 20, 110, 70), m);
  }

  @Test
  void rotatedAreaMovesRigidly() {
    ArMapObject a = ArMapObject.forbiddenArea(1000, 2000, 400, 200, 30);
    ArMapObject m = MapGeometry.translate(a, -300, 500);
    assertArrayEquals(new double[] {700, 2500}, MapGeometry.center(m), 1e-6);
    assertArrayEquals(MapGeometry.areaSize(a), MapGeometry.areaSize(m), 1e-6);
    assertEquals(30, m.pose().th(), 1e-9);
    assertTrue(m.contains(700, 2500));
    assertFalse(m.contains(1000, 2000 + 300));
  }

  @Test
  void headingTurnsAnAreaAboutItsCentre() {
    ArMapObject a = ArMapObject.forbiddenArea(0, 0, 400, 200);
    ArMapObject r = MapGeometry.withHeading(a, 90);
    assertArrayEquals(new double[] {200, 100}, MapGeometry.center(r), 1e-6);
    assertArrayEquals(new double[] {400, 200}, MapGeometry.areaSize(r), 1e-6);
    // Turned a quarter: 200 wide along x, 400 tall along y.
    assertTrue(r.contains(200, 100 + 190));
    assertFalse(r.contains(200 + 190, 100));
    assertEquals(ArMapObject.forbiddenArea(200, 100, 400, 200, 90), r);
  }

  @Test
  void headingOfPointObjectsAndRename() {
    ArMapObject g = ArMapObject.goalWithHeading("G", 1, 2, 0);
    assertEquals(45, MapGeometry.withHeading(g, 45).pose().th());
    assertEquals("H", MapGeometry.renamed(g, "H").name());
    assertEquals(g.pose(), MapGeometry.renamed(g, "H").pose());
  }

  @Test
  void forbiddenLineMovesBothEnds() {
    ArMapObject l = ArMapObject.forbiddenLine(0, 0, 100, 0);
    ArMapObject m = MapGeometry.translate(l, 5, 5);
    assertEquals(new ArLineSegment(5, 5, 105, 5), m.getFromToSegment());
  }

  @Test
  void distancesForPicking() {
    assertEquals(5, MapGeometry.distance(ArMapObject.goal("g", 0, 0), 3, 4), 1e-9);
    assertEquals(0, MapGeometry.distance(ArMapObject.forbiddenArea(0, 0, 10, 10), 5, 5), 1e-9);
    assertEquals(2, MapGeometry.distance(ArMapObject.forbiddenArea(0, 0, 10, 10), 12, 5), 1e-9);
    assertEquals(5, MapGeometry.segmentDistance(new ArLineSegment(0, 0, 10, 0), 13, 4), 1e-9);
  }

  @Test
  void insideBox() {
    assertTrue(MapGeometry.inside(ArMapObject.forbiddenLine(1, 1, 9, 9), 0, 0, 10, 10));
    assertFalse(MapGeometry.inside(ArMapObject.forbiddenLine(1, 1, 19, 9), 0, 0, 10, 10));
    assertTrue(MapGeometry.inside(ArMapObject.goal("g", 5, 5), 10, 10, 0, 0));
  }
}
