package org.jaria.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

/** A map's cost, counted before building: never less than what the index then holds. */
class MapCostTest {

  private static int built(List<ArLineSegment> lines, int[] xs, int[] ys, double r) {
    return new WorldMap("t", lines, xs, ys, r, ArPose.ORIGIN).buildIndex(List.of()).cellEntries();
  }

  @Test
  void theBoundHoldsAndStaysCloseOnRandomMaps() {
    SplittableRandom rnd = new SplittableRandom(7);
    for (int round = 0; round < 40; round++) {
      int span = 1000 + rnd.nextInt(2_000_000);
      List<ArLineSegment> lines = new ArrayList<>();
      int nl = rnd.nextInt(300);
      for (int i = 0; i < nl; i++) {
        int len = rnd.nextBoolean() ? 2000 : span;
        double x = rnd.nextInt(span);
        double y = rnd.nextInt(span);
        lines.add(
            new ArLineSegment(
                x, y, x + rnd.nextInt(-len, len + 1), y + rnd.nextInt(-len, len + 1)));
      }
      int np = rnd.nextInt(2000);
      int[] xs = new int[np];
      int[] ys = new int[np];
      for (int i = 0; i < np; i++) {
        xs[i] = rnd.nextInt(span);
        ys[i] = rnd.nextInt(span);
      }
      double r = 5 + rnd.nextInt(100);
      MapCost c = MapCost.of(lines, xs, ys, r);
      int actual = built(lines, xs, ys, r);
      assertEquals(nl, c.lines());
      assertEquals(np, c.points());
      assertTrue(c.cellEntries() >= actual, "round " + round + ": " + c + " < " + actual);
      assertTrue(c.cellEntries() <= 4L * actual + 8, "round " + round + ": " + c + " vs " + actual);
    }
  }

  @Test
  void longWallsCostWhatTheyCrossNotWhatTheyWeigh() {
    List<ArLineSegment> lines = new ArrayList<>();
    for (int i = 0; i < 1000; i++) {
      lines.add(new ArLineSegment(0, i * 4000.0, 4_000_000, 4_000_000 - i * 4000.0));
    }
    MapCost c = MapCost.of(lines, new int[0], new int[0], 50);
    assertEquals(1000, c.lines());
    assertTrue(c.cellEntries() > 3_000_000, "a thousand walls 5.6 km long: " + c);
    assertTrue(MapCost.of(lines.subList(0, 1), new int[0], new int[0], 50).cellEntries() < 8000);
  }
}
