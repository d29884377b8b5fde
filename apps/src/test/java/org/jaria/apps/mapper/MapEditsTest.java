package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.BitSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;
import org.junit.jupiter.api.Test;

class MapEditsTest {

  private final AtomicLong ids = new AtomicLong(100);

  private MapContent sample() {
    return new MapContent(
        List.of(
            new MapLine(1, new ArLineSegment(0, 0, 1000, 0)),
            new MapLine(2, new ArLineSegment(0, 0, 0, 1000))),
        ArMapPoints.of(new int[] {10, 20, 30}, new int[] {1, 2, 3}),
        List.of(
            new MapObjectEntry(3, ArMapObject.goal("A", 500, 500)),
            new MapObjectEntry(4, ArMapObject.forbiddenArea(0, 0, 100, 200))));
  }

  @Test
  void addAppendsWithFreshNumbers() {
    MapContent c =
        MapEdits.add(
                "Add",
                List.of(new ArLineSegment(1, 2, 3, 4)),
                List.of(ArMapObject.dock("D", 0, 0, 90)))
            .apply(sample(), ids::getAndIncrement);
    assertEquals(3, c.lines().size());
    assertEquals(100, c.lines().get(2).id());
    assertEquals(101, c.objects().get(2).id());
    assertEquals("D", c.objects().get(2).object().name());
  }

  @Test
  void addPointsKeepsTheOldOnes() {
    MapContent c =
        MapEdits.addPoints(new int[] {7}, new int[] {8}).apply(sample(), ids::getAndIncrement);
    assertEquals(ArMapPoints.of(new int[] {10, 20, 30, 7}, new int[] {1, 2, 3, 8}), c.points());
  }

  @Test
  void deleteRemovesItemsAndPoints() {
    BitSet p = new BitSet();
    p.set(1);
    MapContent c = MapEdits.delete(Set.of(2L, 3L), p).apply(sample(), ids::getAndIncrement);
    assertEquals(List.of(1L), c.lines().stream().map(MapLine::id).toList());
    assertEquals(List.of(4L), c.objects().stream().map(MapObjectEntry::id).toList());
    assertEquals(ArMapPoints.of(new int[] {10, 30}, new int[] {1, 3}), c.points());
  }

  @Test
  void moveShiftsOnlyTheSelection() {
    BitSet p = new BitSet();
    p.set(0);
    MapContent before = sample();
    MapContent c =
        MapEdits.move(Set.of(1L, 3L, 4L), p, 100, -50).apply(before, ids::getAndIncrement);
    assertEquals(new ArLineSegment(100, -50, 1100, -50), c.lines().get(0).segment());
    assertSame(before.lines().get(1), c.lines().get(1));
    assertEquals(600, c.objects().get(0).object().pose().x());
    assertEquals(ArMapObject.forbiddenArea(100, -50, 200, 150), c.objects().get(1).object());
    assertEquals(110, c.points().x(0));
    assertEquals(-49, c.points().y(0));
    assertEquals(20, c.points().x(1));
  }

  @Test
  void replaceKeepsPlaceAndNumber() {
    MapContent c =
        MapEdits.replace("Rename", 3, ArMapObject.goal("B", 500, 500))
            .apply(sample(), ids::getAndIncrement);
    assertEquals(3, c.objects().get(0).id());
    assertEquals("B", c.objects().get(0).object().name());
  }
}
