package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.world.WorldMap;
import org.junit.jupiter.api.Test;

/** MobileSim's {@code --start} values, parsed without a command-line library. */
class StartPlaceTest {

  @Test
  void startPlacesOutsideAndRandomFollowTheMapBounds() {
    WorldMap box =
        WorldMap.ofLines(
            "box",
            List.of(new ArLineSegment(0, 0, 10_000, 0), new ArLineSegment(0, 0, 0, 8_000)),
            ArPose.ORIGIN);
    ArPose out = StartPlace.parse("outside").poseFor(1, box, new SplittableRandom(1));
    assertEquals(
        new ArPose(-2_000, 7_000, 0),
        out,
        "2 m left of the map, level with its top, 1 m per robot");
    StartPlace random = StartPlace.parse("random");
    ArPose a = random.poseFor(0, box, new SplittableRandom(7));
    assertEquals(a, random.poseFor(0, box, new SplittableRandom(7)), "the seed decides");
    assertTrue(a.x() >= 0 && a.x() <= 10_000 && a.y() >= 0 && a.y() <= 8_000, a.toString());
    assertEquals(
        new ArPose(5, -994, 7),
        StartPlace.parse("5,6,7").poseFor(1, box, null),
        "a fixed pose applies to every robot, in MobileSim's row 1 m apart");
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> StartPlace.parse("1,2"));
    assertTrue(e.getMessage().contains("outside or random"), e.getMessage());
  }

  @Test
  void aFixedPoseIsTheFirstRobotsAndSpacesAndCaseDoNotMatter() {
    StartPlace p = StartPlace.parse(" 200, 4650 ,90 ");
    assertEquals(StartPlace.Kind.FIXED, p.kind());
    assertEquals(
        new ArPose(200, 4650, 90),
        p.poseFor(0, WorldMap.ofLines("e", List.of(), ArPose.ORIGIN), null));
    assertEquals(StartPlace.Kind.OUTSIDE, StartPlace.parse("OUTSIDE").kind());
    assertThrows(IllegalArgumentException.class, () -> StartPlace.parse("1.5,2,3"));
    assertThrows(IllegalArgumentException.class, () -> StartPlace.parse(""));
  }

  @Test
  void anEmptyMapIsATenMetreSquareAtTheOrigin() {
    WorldMap empty = WorldMap.ofLines("empty", List.of(), ArPose.ORIGIN);
    assertEquals(
        new ArPose(-5000 - StartPlace.OUTSIDE_MARGIN, 5000, 0),
        StartPlace.parse("outside").poseFor(0, empty, new SplittableRandom(1)));
  }
}
