package org.jaria.arnl.plan;

import org.jaria.arnl.grid.GridSpec;

/**
 * A* search over the 8-connected cells of a {@link CostGrid}: a step costs its length (mm) times
 * the mean cost of the two cells, and the heuristic is the octile distance (admissible, since no
 * cell costs less than 1 per mm), so the result is a cheapest path. Working arrays are kept between
 * searches and reset by generation stamps, so a search allocates only its result. Not thread-safe:
 * one planner per thread.
 */
public final class AStarPlanner {

  private static final int[] DI = {1, -1, 0, 0, 1, 1, -1, -1};
  private static final int[] DJ = {0, 0, 1, -1, 1, -1, 1, -1};
  private static final double SQRT2 = Math.sqrt(2);

  private int[] seen = new int[0];
  private int[] closed = new int[0];
  private float[] g = new float[0];
  private int[] parent = new int[0];
  private int stamp;
  private float[] heapKey = new float[1024];
  private int[] heapCell = new int[1024];
  private int heapSize;
  private int expanded;

  /**
   * The cheapest path of cells from {@code start} to {@code goal} (both included), or null if none
   * exists. Both cells must be free.
   */
  public int[] plan(CostGrid grid, int start, int goal) {
    GridSpec s = grid.spec();
    int n = s.size();
    if (seen.length < n) {
      seen = new int[n];
      closed = new int[n];
      g = new float[n];
      parent = new int[n];
      stamp = 0;
    }
    if (++stamp == Integer.MAX_VALUE) {
      java.util.Arrays.fill(seen, 0);
      java.util.Arrays.fill(closed, 0);
      stamp = 1;
    }
    expanded = 0;
    heapSize = 0;
    if (!grid.isFree(start) || !grid.isFree(goal)) {
      return null;
    }
    int w = s.width();
    int h = s.height();
    double res = s.res();
    int gi = goal % w;
    int gj = goal / w;
    seen[start] = stamp;
    g[start] = 0;
    parent[start] = -1;
    push(heuristic(start % w, start / w, gi, gj, res), start);
    while (heapSize > 0) {
      int cur = pop();
      if (closed[cur] == stamp) {
        continue;
      }
      closed[cur] = stamp;
      expanded++;
      if (cur == goal) {
        return extract(goal);
      }
      int ci = cur % w;
      int cj = cur / w;
      float cc = grid.cost(cur);
      float gc = g[cur];
      for (int d = 0; d < 8; d++) {
        int ni = ci + DI[d];
        int nj = cj + DJ[d];
        if (ni < 0 || nj < 0 || ni >= w || nj >= h) {
          continue;
        }
        int nb = nj * w + ni;
        float nc = grid.cost(nb);
        if (nc == Float.POSITIVE_INFINITY || closed[nb] == stamp) {
          continue;
        }
        if (d >= 4 && (!grid.isFree(cj * w + ni) || !grid.isFree(nj * w + ci))) {
          // No cutting corners between two blocked cells.
          continue;
        }
        double step = (d < 4 ? res : res * SQRT2) * 0.5 * (cc + nc);
        float ng = (float) (gc + step);
        if (seen[nb] != stamp || ng < g[nb]) {
          seen[nb] = stamp;
          g[nb] = ng;
          parent[nb] = cur;
          push((float) (ng + heuristic(ni, nj, gi, gj, res)), nb);
        }
      }
    }
    return null;
  }

  /** Cells expanded by the last search. */
  public int expandedCount() {
    return expanded;
  }

  private static double heuristic(int i, int j, int gi, int gj, double res) {
    int dx = Math.abs(i - gi);
    int dy = Math.abs(j - gj);
    int mn = Math.min(dx, dy);
    int mx = Math.max(dx, dy);
    return res * (mx - mn + SQRT2 * mn);
  }

  private int[] extract(int goal) {
    int len = 0;
    for (int c = goal; c >= 0; c = parent[c]) {
      len++;
    }
    int[] path = new int[len];
    int k = len;
    for (int c = goal; c >= 0; c = parent[c]) {
      path[--k] = c;
    }
    return path;
  }

  private void push(double key, int cell) {
    if (heapSize == heapKey.length) {
      heapKey = java.util.Arrays.copyOf(heapKey, heapSize * 2);
      heapCell = java.util.Arrays.copyOf(heapCell, heapSize * 2);
    }
    int i = heapSize++;
    float k = (float) key;
    while (i > 0) {
      int p = (i - 1) >>> 1;
      if (heapKey[p] <= k) {
        break;
      }
      heapKey[i] = heapKey[p];
      heapCell[i] = heapCell[p];
      i = p;
    }
    heapKey[i] = k;
    heapCell[i] = cell;
  }

  private int pop() {
    int top = heapCell[0];
    heapSize--;
    if (heapSize > 0) {
      float k = heapKey[heapSize];
      int c = heapCell[heapSize];
      int i = 0;
      while (true) {
        int l = 2 * i + 1;
        if (l >= heapSize) {
          break;
        }
        int r = l + 1;
        int m = r < heapSize && heapKey[r] < heapKey[l] ? r : l;
        if (heapKey[m] >= k) {
          break;
        }
        heapKey[i] = heapKey[m];
        heapCell[i] = heapCell[m];
        i = m;
      }
      heapKey[i] = k;
      heapCell[i] = c;
    }
    return top;
  }
}
