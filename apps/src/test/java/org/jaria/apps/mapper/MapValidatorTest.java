package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.apps.fx.TestFiles;
import org.jaria.apps.mapper.MapProblem.Severity;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class MapValidatorTest {

  @TempDir Path dir;

  private static MapContent of(List<MapLine> lines, ArMapObject... objects) {
    List<MapObjectEntry> e = new ArrayList<>();
    long id = 100;
    for (ArMapObject o : objects) {
      e.add(new MapObjectEntry(id++, o));
    }
    return new MapContent(lines, ArMapPoints.EMPTY, e);
  }

  @Test
  void columbiaHasItsGoalInsideAForbiddenAreaAsAWarningNotAnError() throws Exception {
    AtomicLong ids = new AtomicLong(1);
    MapContent c = MapFile.read(TestFiles.columbiaCopy(dir), ids::getAndIncrement).content();
    List<MapProblem> p = new MapValidator().validate(c);
    assertEquals(1, p.size(), p::toString);
    // A goal placed there on purpose (ARIA's map shows path planning refusing it): the map works.
    assertEquals(Severity.WARNING, p.get(0).severity());
    assertTrue(p.get(0).toString().startsWith("Warning: goal 'Inside Forbidden Area'"));
    assertTrue(p.get(0).message().contains("'Inside Forbidden Area'"));
    assertTrue(p.get(0).message().contains("forbidden area"));
  }

  @Test
  void homeInsideAreaAndGoalInWall() {
    MapContent c =
        of(
            List.of(new MapLine(1, new ArLineSegment(0, 0, 0, 5000))),
            ArMapObject.forbiddenArea(1000, 1000, 2000, 2000),
            ArMapObject.robotHome("", 1500, 1500, 0),
            ArMapObject.goal("Wall", 100, 2500));
    List<MapProblem> p = new MapValidator().validate(c);
    assertEquals(2, p.size(), p::toString);
    assertTrue(p.get(0).message().startsWith("home at (1500, 1500) is inside a forbidden area"));
    assertTrue(p.get(1).message().startsWith("goal 'Wall' at (100, 2500) is 100 mm from a wall"));
    assertEquals(101, p.get(0).itemId());
    assertEquals(Severity.ERROR, p.get(0).severity(), "the home: the map does not work");
    assertEquals(Severity.WARNING, p.get(1).severity(), "one goal: that goal does not work");
  }

  @Test
  void goalNearSensorPointsIsInAWall() {
    MapContent c =
        new MapContent(
            List.of(),
            ArMapPoints.of(new int[] {0}, new int[] {100}),
            List.of(
                new MapObjectEntry(1, ArMapObject.goal("G", 0, 0)),
                new MapObjectEntry(2, ArMapObject.robotHome("", 0, 5000, 0))));
    List<MapProblem> p = new MapValidator().validate(c);
    assertEquals(1, p.size(), p::toString);
    assertTrue(p.get(0).message().contains("100 mm from a wall"));
  }

  @Test
  void warningsForNamesHomeAndEmptyAreas() {
    MapContent c =
        of(
            List.of(),
            ArMapObject.goal("", 0, 0),
            ArMapObject.goal("Same", 5000, 0),
            ArMapObject.goal("same", 10000, 0),
            ArMapObject.forbiddenArea(20000, 0, 20000, 100));
    List<MapProblem> p = new MapValidator().validate(c);
    assertEquals(5, p.size(), p::toString);
    assertTrue(p.stream().allMatch(x -> x.severity() == Severity.WARNING));
    assertTrue(p.get(0).message().contains("has no name"));
    assertTrue(p.get(1).message().contains("same name"));
    assertTrue(p.get(2).message().contains("same name"));
    assertTrue(p.get(3).message().contains("has no area"));
    assertTrue(p.get(4).message().contains("no home"));
  }

  @Test
  void emptyMapHasNoProblems() {
    assertTrue(new MapValidator().validate(MapContent.EMPTY).isEmpty());
  }
}
