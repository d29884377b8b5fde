package org.jaria.arnl.grid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

class DistanceFieldTest {

  @Test
  void matchesBruteForceOnRandomGrids() {
    Random rnd = new Random(7);
    for (int trial = 0; trial < 20; trial++) {
      int w = 5 + rnd.nextInt(40);
      int h = 5 + rnd.nextInt(40);
      GridSpec g = new GridSpec(0, 0, 10, w, h);
      boolean[] occ = new boolean[w * h];
      int obstacles = rnd.nextInt(6);
      for (int k = 0; k < obstacles; k++) {
        occ[rnd.nextInt(w * h)] = true;
      }
      float[] d = DistanceField.compute(occ, g, 1e6);
      for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
          double best = 1e6;
          for (int k = 0; k < w * h; k++) {
            if (occ[k]) {
              best = Math.min(best, 10 * Math.hypot(i - k % w, j - k / w));
            }
          }
          assertEquals(best, d[j * w + i], 1e-2, "cell " + i + "," + j + " of trial " + trial);
        }
      }
    }
  }

  @Test
  void capsDistances() {
    GridSpec g = new GridSpec(0, 0, 100, 50, 3);
    boolean[] occ = new boolean[150];
    occ[0] = true;
    float[] d = DistanceField.compute(occ, g, 1000);
    assertEquals(0, d[0]);
    assertEquals(1000, d[49]);
  }

  @Test
  void rasterizedLinesAreWatertightAndForbiddenAreasFilled() {
    ArMap map = new ArMap();
    map.setLines(List.of(new ArLineSegment(0, 0, 3000, 1700), new ArLineSegment(0, 0, 0, 2000)));
    map.addMapObject(ArMapObject.forbiddenArea(1000, 1000, 1500, 1400));
    GridSpec g = MapRaster.specFor(map, 50, 200);
    boolean[] occ = MapRaster.walls(map, g);
    // A diagonal line drawn 4-connected: every occupied cell has an occupied 4-neighbour.
    int lonely = 0;
    int count = 0;
    for (int j = 1; j < g.height() - 1; j++) {
      for (int i = 1; i < g.width() - 1; i++) {
        int k = j * g.width() + i;
        if (!occ[k]) {
          continue;
        }
        count++;
        if (!occ[k - 1] && !occ[k + 1] && !occ[k - g.width()] && !occ[k + g.width()]) {
          lonely++;
        }
      }
    }
    assertTrue(count > 60, "lines should occupy cells");
    assertEquals(0, lonely, "no isolated cells: the chain is 4-connected");
    assertTrue(!occ[g.indexOf(1250, 1200)], "forbidden areas are not walls");
    MapRaster.addForbidden(occ, g, map);
    assertTrue(occ[g.indexOf(1250, 1200)], "forbidden area filled for planning");
  }
}
