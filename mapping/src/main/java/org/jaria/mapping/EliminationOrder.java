package org.jaria.mapping;

import java.util.Arrays;

/**
 * An order in which to eliminate the poses of a pose graph so that the sparse Cholesky factor stays
 * sparse: reverse Cuthill-McKee, a breadth-first walk of the graph from its first free pose that
 * takes the least connected neighbours first, reversed. A robot that drives the same corridor three
 * times gives poses that are far apart in driving order but joined by loop closures; the walk puts
 * them next to each other, so the factor is a narrow band instead of filling in between the laps.
 * EJML's sparse Cholesky offers no such ordering of its own (only none or random).
 */
final class EliminationOrder {

  private EliminationOrder() {}

  /**
   * The new position (1..nodes-1) of every pose 1..nodes-1 of a graph with {@code edges} edges
   * (ei[k], ej[k]); pose 0, held fixed, stays 0.
   */
  static int[] reverseCuthillMcKee(int nodes, int[] ei, int[] ej, int edges) {
    int[] degree = new int[nodes];
    for (int k = 0; k < edges; k++) {
      if (ei[k] != ej[k]) {
        degree[ei[k]]++;
        degree[ej[k]]++;
      }
    }
    int[] start = new int[nodes + 1];
    for (int i = 0; i < nodes; i++) {
      start[i + 1] = start[i] + degree[i];
    }
    int[] fill = Arrays.copyOf(start, nodes);
    int[] adj = new int[start[nodes]];
    for (int k = 0; k < edges; k++) {
      if (ei[k] != ej[k]) {
        adj[fill[ei[k]]++] = ej[k];
        adj[fill[ej[k]]++] = ei[k];
      }
    }
    int[] walk = new int[nodes];
    boolean[] seen = new boolean[nodes];
    seen[0] = true;
    int len = 0;
    for (int root = 1; root < nodes; root++) {
      if (seen[root]) {
        continue;
      }
      seen[root] = true;
      walk[len++] = root;
      for (int head = len - 1; head < len; head++) {
        int v = walk[head];
        int first = len;
        for (int a = start[v]; a < start[v + 1]; a++) {
          int u = adj[a];
          if (!seen[u]) {
            seen[u] = true;
            walk[len++] = u;
          }
        }
        sortByDegree(walk, first, len, degree);
      }
    }
    int[] order = new int[nodes];
    for (int k = 0; k < len; k++) {
      order[walk[k]] = len - k;
    }
    return order;
  }

  /** Insertion sort of walk[from..to) by degree (a pose has few neighbours). */
  private static void sortByDegree(int[] walk, int from, int to, int[] degree) {
    for (int i = from + 1; i < to; i++) {
      int v = walk[i];
      int j = i - 1;
      while (j >= from && degree[walk[j]] > degree[v]) {
        walk[j + 1] = walk[j];
        j--;
      }
      walk[j + 1] = v;
    }
  }
}
