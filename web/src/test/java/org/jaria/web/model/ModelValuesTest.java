package org.jaria.web.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

/** The frame model is plain values: equal when their contents are equal, checked when made. */
class ModelValuesTest {

  static RobotFrame robot(String name, double x) {
    return new RobotFrame(
        name,
        "p3dx-sh",
        new ArPose(x, 0, 90),
        null,
        Points.of(1, 2, 3, 4, 5, 6),
        Points.of(0, 0),
        Points.of(100, 0),
        new LaserFrame(new ArPose(x, 0, 90), -90, 1, new int[] {1000, 2000}),
        Points.EMPTY,
        Points.EMPTY,
        null,
        new RobotStatus(100, 5, Double.NaN, true, false, "no client", Double.NaN));
  }

  @Test
  void pointsAreValuesAndCopied() {
    float[] xy = {1, 2, 3, 4};
    Points p = Points.of(xy);
    xy[0] = 99;
    assertEquals(1, p.x(0));
    assertEquals(Points.of(1, 2, 3, 4), p);
    assertNotEquals(Points.of(1, 2, 3, 5), p);
    assertEquals(Points.of(1, 2, 3, 4).hashCode(), p.hashCode());
    float[] out = p.toArray();
    out[1] = 77;
    assertEquals(2, p.y(0));
    assertEquals(2, p.size());
    assertTrue(Points.of().isEmpty());
    assertThrows(IllegalArgumentException.class, () -> Points.of(1, 2, 3));
  }

  @Test
  void theBuilderGrowsAndHandsOverWhatWasAdded() {
    Points.Builder b = Points.builder(1);
    for (int i = 0; i < 100; i++) {
      b.add(i, -i);
    }
    Points p = b.build();
    assertEquals(100, p.size());
    assertEquals(99, p.x(99));
    assertEquals(-99, p.y(99));
  }

  @Test
  void framesAreEqualWhenTheirContentsAre() {
    assertEquals(robot("a", 1), robot("a", 1));
    assertNotEquals(robot("a", 1), robot("a", 2));
    ClockFrame c = new ClockFrame(5, 1, false, true);
    assertEquals(
        new WorldFrame(c, List.of(robot("a", 1))), new WorldFrame(c, List.of(robot("a", 1))));
    assertEquals(
        new LaserFrame(ArPose.ORIGIN, -90, 1, new int[] {1, 2}),
        new LaserFrame(ArPose.ORIGIN, -90, 1, new int[] {1, 2}));
    assertNotEquals(
        new LaserFrame(ArPose.ORIGIN, -90, 1, new int[] {1, 2}),
        new LaserFrame(ArPose.ORIGIN, -90, 1, new int[] {1, 3}));
  }

  @Test
  void aFrameRefusesTwoRobotsOfOneNameAndUnevenSonar() {
    ClockFrame c = ClockFrame.real(0);
    var e =
        assertThrows(
            IllegalArgumentException.class,
            () -> new WorldFrame(c, List.of(robot("a", 1), robot("a", 2))));
    assertTrue(e.getMessage().contains("two robots are named a"), e.getMessage());
    RobotFrame r = robot("a", 1);
    assertThrows(
        IllegalArgumentException.class,
        () ->
            new RobotFrame(
                "a",
                "m",
                null,
                null,
                Points.EMPTY,
                Points.of(0, 0),
                Points.EMPTY,
                null,
                Points.EMPTY,
                Points.EMPTY,
                null,
                r.status()));
  }

  @Test
  void theShownPoseIsTheTrueOneWhenKnown() {
    RobotFrame r = robot("a", 1);
    assertEquals(r.truePose(), r.shownPose());
    RobotFrame nav =
        r.withNavigation(new ArPose(5, 5, 0), Points.of(1, 1), Points.EMPTY, null, r.status());
    assertEquals(r.truePose(), nav.shownPose());
    assertEquals(new ArPose(5, 5, 0), nav.believedPose());
    assertEquals(Points.of(1, 1), nav.particles());
  }

  @Test
  void boundsEncloseEveryPoint() {
    MapLayer.Bounds b = MapLayer.Bounds.around(Points.of(-5, 2, 10, -3), Points.of(0, 40));
    assertEquals(new MapLayer.Bounds(-5, -3, 10, 40), b);
    assertEquals(new MapLayer.Bounds(-1000, -1000, 1000, 1000), MapLayer.Bounds.around());
  }
}
