package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class EliminationOrderTest {

  /** Three laps of 100 poses each, every pose of a later lap closed onto the first lap's. */
  @Test
  void lapsClosedOntoTheFirstAreNumberedSideBySide() {
    int laps = 3;
    int perLap = 100;
    int nodes = laps * perLap;
    int[] ei = new int[2 * nodes];
    int[] ej = new int[2 * nodes];
    int edges = 0;
    for (int i = 1; i < nodes; i++) {
      ei[edges] = i - 1;
      ej[edges++] = i;
    }
    for (int i = perLap; i < nodes; i++) {
      ei[edges] = i % perLap;
      ej[edges++] = i;
    }
    int[] order = EliminationOrder.reverseCuthillMcKee(nodes, ei, ej, edges);
    assertEquals(0, order[0], "the fixed pose stays first");
    boolean[] used = new boolean[nodes];
    for (int i = 1; i < nodes; i++) {
      assertTrue(order[i] >= 1 && order[i] < nodes && !used[order[i]], "a permutation of 1..n-1");
      used[order[i]] = true;
    }
    int widest = 0;
    int widestInDrivingOrder = 0;
    for (int k = 0; k < edges; k++) {
      if (ei[k] != 0) {
        widest = Math.max(widest, Math.abs(order[ei[k]] - order[ej[k]]));
      }
      widestInDrivingOrder = Math.max(widestInDrivingOrder, Math.abs(ei[k] - ej[k]));
    }
    assertEquals(2 * perLap, widestInDrivingOrder);
    assertTrue(
        widest <= 10, "bandwidth " + widest + " (driving order: " + widestInDrivingOrder + ")");
  }
}
