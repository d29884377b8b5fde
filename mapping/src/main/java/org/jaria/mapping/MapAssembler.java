package org.jaria.mapping;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LogTag;
import org.jaria.map.ArMapObject;

/**
 * Turns the optimised graph into a map: every pose's points placed by its estimate and thinned to
 * one per map cell (a cell hit by a single reading with no hit around it is dropped as noise), the
 * walls' lines, the start as RobotHome and the logged goals.
 */
final class MapAssembler {

  private MapAssembler() {}

  static BuiltMap assemble(
      Nodes nodes,
      Trajectory trajectory,
      MapBuilderParams params,
      List<LogTag> tags,
      List<int[]> tagNodes,
      List<ArPose> tagOffsets,
      BuiltMap.Stats stats) {
    int res = params.resolutionMm();
    CellCounts cells = new CellCounts(1 << 16);
    LineFitter lines = new LineFitter();
    double[] gx = new double[4096];
    double[] gy = new double[4096];
    for (int i = 0; i < nodes.size(); i++) {
      addKept(nodes, i, cells, res);
      ScanPoints p = nodes.points(i);
      if (p == null) {
        continue;
      }
      if (gx.length < p.count) {
        gx = new double[p.count];
        gy = new double[p.count];
      }
      int n = place(nodes, i, p, gx, gy);
      for (int k = 0; k < n; k++) {
        cells.add((int) Math.floor(gx[k] / res), (int) Math.floor(gy[k] / res), 1);
      }
      lines.addScan(gx, gy, n, nodes.graph.xMm(i), nodes.graph.yMm(i));
    }
    int[] xs = new int[cells.size()];
    int[] ys = new int[cells.size()];
    int n = 0;
    long noise = 0;
    for (int s = 0; s < cells.capacity(); s++) {
      if (!cells.used(s)) {
        continue;
      }
      int cx = CellCounts.keyX(cells.keyAt(s));
      int cy = CellCounts.keyY(cells.keyAt(s));
      if (cells.countAt(s) == 1 && isolated(cells, cx, cy)) {
        noise++;
        continue;
      }
      xs[n] = cx * res + res / 2;
      ys[n] = cy * res + res / 2;
      n++;
    }
    int[][] sorted = sort(Arrays.copyOf(xs, n), Arrays.copyOf(ys, n));
    List<ArMapObject> objects = new ArrayList<>();
    ArPose home = nodes.estimate(0);
    objects.add(ArMapObject.robotHome("", Math.rint(home.x()), Math.rint(home.y()), home.th()));
    for (int t = 0; t < tags.size(); t++) {
      LogTag tag = tags.get(t);
      ArPose p = Poses.compose(nodes.estimate(tagNodes.get(t)[0]), tagOffsets.get(t));
      String type = tag.cairnType().isEmpty() ? "GoalWithHeading" : tag.cairnType();
      objects.add(
          new ArMapObject(
              type,
              new ArPose(Math.rint(p.x()), Math.rint(p.y()), Math.rint(p.th() * 100) / 100.0),
              "",
              tag.cairnName()));
    }
    List<ArLineSegment> walls = lines.lines();
    return new BuiltMap(
        sorted[0], sorted[1], walls, objects, res, trajectory, stats.withNoise(noise));
  }

  private static boolean isolated(CellCounts cells, int cx, int cy) {
    for (int dy = -1; dy <= 1; dy++) {
      for (int dx = -1; dx <= 1; dx++) {
        if ((dx != 0 || dy != 0) && cells.get(cx + dx, cy + dy) > 0) {
          return false;
        }
      }
    }
    return true;
  }

  /**
   * Adds the cells node {@code i} keeps of pruned poses (in its frame) to {@code cells} (cells of
   * {@code cell} mm in the map frame), with their counts.
   */
  private static void addKept(Nodes nodes, int i, CellCounts cells, int cell) {
    int res = nodes.keptResolution();
    CellCounts kept = nodes.keptCells(i);
    if (kept == null) {
      return;
    }
    double t = nodes.graph.thRad(i);
    double c = Math.cos(t);
    double s = Math.sin(t);
    double x = nodes.graph.xMm(i);
    double y = nodes.graph.yMm(i);
    for (int slot = 0; slot < kept.capacity(); slot++) {
      if (!kept.used(slot)) {
        continue;
      }
      long key = kept.keyAt(slot);
      double lx = (CellCounts.keyX(key) + 0.5) * res;
      double ly = (CellCounts.keyY(key) + 0.5) * res;
      double gx = x + c * lx - s * ly;
      double gy = y + s * lx + c * ly;
      cells.add((int) Math.floor(gx / cell), (int) Math.floor(gy / cell), kept.countAt(slot));
    }
  }

  /** Node i's points within the map range, in the map frame; returns how many. */
  private static int place(Nodes nodes, int i, ScanPoints p, double[] gx, double[] gy) {
    double t = nodes.graph.thRad(i);
    double c = Math.cos(t);
    double s = Math.sin(t);
    double x = nodes.graph.xMm(i);
    double y = nodes.graph.yMm(i);
    int n = 0;
    for (int k = 0; k < p.count; k++) {
      if (p.inMapRange[k]) {
        gx[n] = x + c * p.px[k] - s * p.py[k];
        gy[n] = y + s * p.px[k] + c * p.py[k];
        n++;
      }
    }
    return n;
  }

  /** Points in ARIA's order (by x, then y). */
  static int[][] sort(int[] xs, int[] ys) {
    long[] keys = new long[xs.length];
    for (int i = 0; i < xs.length; i++) {
      keys[i] = ((long) xs[i] << 32) + ((long) ys[i] - Integer.MIN_VALUE);
    }
    Arrays.sort(keys);
    int[] sx = new int[xs.length];
    int[] sy = new int[xs.length];
    for (int i = 0; i < keys.length; i++) {
      long k = keys[i];
      long yPart = k & 0xffffffffL;
      sx[i] = (int) ((k - yPart) >> 32);
      sy[i] = (int) (yPart + Integer.MIN_VALUE);
    }
    return new int[][] {sx, sy};
  }

  /** The map so far at 50 mm, and the path. */
  static MapSnapshot snapshot(Nodes nodes) {
    CellCounts cells = new CellCounts(1 << 12);
    double[] gx = new double[256];
    double[] gy = new double[256];
    double[] px = new double[nodes.size()];
    double[] py = new double[nodes.size()];
    for (int i = 0; i < nodes.size(); i++) {
      px[i] = nodes.graph.xMm(i);
      py[i] = nodes.graph.yMm(i);
      addKept(nodes, i, cells, 50);
      ScanPoints p = nodes.points(i);
      if (p == null) {
        continue;
      }
      if (gx.length < p.count) {
        gx = new double[p.count];
        gy = new double[p.count];
      }
      int n = place(nodes, i, p, gx, gy);
      for (int k = 0; k < n; k++) {
        cells.add((int) Math.floor(gx[k] / 50), (int) Math.floor(gy[k] / 50), 1);
      }
    }
    int[] xs = new int[cells.size()];
    int[] ys = new int[cells.size()];
    int n = 0;
    for (int s = 0; s < cells.capacity(); s++) {
      if (cells.used(s)) {
        xs[n] = CellCounts.keyX(cells.keyAt(s)) * 50 + 25;
        ys[n] = CellCounts.keyY(cells.keyAt(s)) * 50 + 25;
        n++;
      }
    }
    ArPose pose = nodes.size() == 0 ? ArPose.ORIGIN : nodes.estimate(nodes.size() - 1);
    return new MapSnapshot(xs, ys, px, py, pose);
  }
}
