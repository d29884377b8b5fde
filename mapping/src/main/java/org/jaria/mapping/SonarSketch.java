package org.jaria.mapping;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.jaria.geom.ArPose;

/**
 * A rough occupancy sketch from sonar readings, for robots without a laser: each echo marks the arc
 * at its range as probably occupied and the cone before it as probably free (log-odds on a grid of
 * {@link #CELL_MM} cells). It is drawn from the robot's odometry as it is, uncorrected: walls blur
 * and bend as the odometry drifts. It is a background for tracing walls in the map editor, <b>not a
 * map to localize on</b>: {@link #writeMap} writes its cells as a map's points with no lines, and
 * says so in the file.
 *
 * <pre>{@code
 * SonarSketch s = new SonarSketch();
 * s.add(robot.getPose(), r.getSensorX(), r.getSensorY(), r.getSensorTh(), r.getRange());
 * s.writeMap(Path.of("sketch.map"));
 * }</pre>
 */
public final class SonarSketch {

  /** Grid cell size, mm. */
  public static final int CELL_MM = 100;

  /** Echoes at or beyond this range are taken as no echo (only free space is marked), mm. */
  public static final int MAX_RANGE_MM = 4000;

  /** Half the sonar's cone, degrees (a Pioneer's transducers see about 15 degrees). */
  static final double HALF_CONE_DEG = 7.5;

  /** A cell counts as occupied above this log-odds. */
  static final float OCCUPIED = 1.2f;

  private static final float HIT = 0.7f;
  private static final float MISS = -0.35f;
  private static final float LIMIT = 5f;

  /** The map file's label: ARIA's readers skip header keys they do not know. */
  public static final String LABEL =
      "JAriaSketch: \"sonar sketch from odometry: trace the walls with lines in the map editor;"
          + " not a map for localization\"";

  private int minCx;
  private int minCy;
  private int width;
  private int height;
  private float[] odds = new float[0];
  private long readings;

  /** Echoes added (not counting no-echo readings). */
  public long readings() {
    return readings;
  }

  /**
   * Adds one sonar reading.
   *
   * @param robot the robot's pose when the reading was taken (odometry)
   * @param sensorX the transducer's position on the robot, mm forward
   * @param sensorY mm to the left
   * @param sensorTh the direction it faces on the robot, degrees
   * @param range the range read, mm (negative: none; at or beyond {@link #MAX_RANGE_MM}: no echo)
   */
  public void add(ArPose robot, double sensorX, double sensorY, double sensorTh, double range) {
    if (!(range >= 0) || !Double.isFinite(robot.x() + robot.y() + robot.th())) {
      return;
    }
    double c = Math.cos(robot.getThRad());
    double s = Math.sin(robot.getThRad());
    double ox = robot.x() + c * sensorX - s * sensorY;
    double oy = robot.y() + s * sensorX + c * sensorY;
    double th = Math.toRadians(robot.th() + sensorTh);
    boolean echo = range < MAX_RANGE_MM;
    double free = Math.min(range, MAX_RANGE_MM) - CELL_MM;
    double half = Math.toRadians(HALF_CONE_DEG);
    for (double a = -half; a <= half + 1e-9; a += half) {
      double dx = Math.cos(th + a);
      double dy = Math.sin(th + a);
      for (double d = CELL_MM / 2.0; d < free; d += CELL_MM / 2.0) {
        update(ox + dx * d, oy + dy * d, MISS / 2);
      }
    }
    if (!echo) {
      return;
    }
    readings++;
    // The echo came from somewhere on the arc: the centre most likely, the rim less.
    int steps = 2 * Math.max(1, (int) Math.ceil(half * range / CELL_MM)); // even: the centre too
    for (int i = 0; i <= steps; i++) {
      double a = -half + 2 * half * i / steps;
      double w = 1 - 0.5 * Math.abs(a) / half;
      update(ox + Math.cos(th + a) * range, oy + Math.sin(th + a) * range, HIT * (float) w);
    }
  }

  private void update(double x, double y, float delta) {
    int cx = (int) Math.floor(x / CELL_MM);
    int cy = (int) Math.floor(y / CELL_MM);
    if (!inside(cx, cy)) {
      grow(cx, cy);
    }
    int i = (cy - minCy) * width + (cx - minCx);
    odds[i] = Math.max(-LIMIT, Math.min(LIMIT, odds[i] + delta));
  }

  private boolean inside(int cx, int cy) {
    return cx >= minCx && cy >= minCy && cx < minCx + width && cy < minCy + height;
  }

  /** Grows the grid to hold cell (cx, cy), with room to spare so growth is rare. */
  private void grow(int cx, int cy) {
    if (width == 0) {
      minCx = cx - 32;
      minCy = cy - 32;
      width = 64;
      height = 64;
      odds = new float[width * height];
      return;
    }
    int nMinX = Math.min(minCx, cx - 32);
    int nMinY = Math.min(minCy, cy - 32);
    int nMaxX = Math.max(minCx + width, cx + 33);
    int nMaxY = Math.max(minCy + height, cy + 33);
    int nw = nMaxX - nMinX;
    int nh = nMaxY - nMinY;
    if ((long) nw * nh > 64L << 20) {
      throw new IllegalStateException(
          "the sketch would need more than 64 million cells: are the robot's poses sensible?");
    }
    float[] n = new float[nw * nh];
    for (int row = 0; row < height; row++) {
      System.arraycopy(odds, row * width, n, (row + minCy - nMinY) * nw + (minCx - nMinX), width);
    }
    odds = n;
    minCx = nMinX;
    minCy = nMinY;
    width = nw;
    height = nh;
  }

  /** The log-odds of the cell holding (x, y), mm; 0 if never seen. */
  public float oddsAt(double x, double y) {
    int cx = (int) Math.floor(x / CELL_MM);
    int cy = (int) Math.floor(y / CELL_MM);
    return inside(cx, cy) ? odds[(cy - minCy) * width + (cx - minCx)] : 0;
  }

  /** The centres of the occupied cells, x and y in turn, mm. */
  public int[] occupied() {
    int[] out = new int[64];
    int n = 0;
    for (int row = 0; row < height; row++) {
      for (int col = 0; col < width; col++) {
        if (odds[row * width + col] > OCCUPIED) {
          if (n + 2 > out.length) {
            out = Arrays.copyOf(out, out.length * 2);
          }
          out[n++] = (minCx + col) * CELL_MM + CELL_MM / 2;
          out[n++] = (minCy + row) * CELL_MM + CELL_MM / 2;
        }
      }
    }
    return Arrays.copyOf(out, n);
  }

  /** A copy of the grid: cells across and down, the lower-left corner, a log-odds per cell. */
  public static final class Grid {
    private final int width;
    private final int height;
    private final int minX;
    private final int minY;
    private final float[] odds;

    Grid(int width, int height, int minX, int minY, float[] odds) {
      this.width = width;
      this.height = height;
      this.minX = minX;
      this.minY = minY;
      this.odds = odds;
    }

    /** Cells across. */
    public int width() {
      return width;
    }

    /** Cells down. */
    public int height() {
      return height;
    }

    /** X of the grid's left edge, mm. */
    public int minX() {
      return minX;
    }

    /** Y of the grid's bottom edge, mm. */
    public int minY() {
      return minY;
    }

    /** The log-odds of cell ({@code col}, {@code row}), row 0 at the bottom; 0: unknown. */
    public float odds(int col, int row) {
      return odds[row * width + col];
    }
  }

  /** A copy of the grid (for a picture). */
  public Grid grid() {
    return new Grid(width, height, minCx * CELL_MM, minCy * CELL_MM, odds.clone());
  }

  /**
   * Writes the occupied cells as an ARIA {@code .map}'s points (no lines, no goals), labelled as a
   * sketch in its header, for the map editor to show under the walls one traces.
   */
  public void writeMap(Path file) throws IOException {
    try (Writer w = Files.newBufferedWriter(file, StandardCharsets.ISO_8859_1)) {
      writeMap(w);
    }
  }

  /** As {@link #writeMap(Path)}, to a writer. */
  public void writeMap(Writer w) throws IOException {
    int[] xy = occupied();
    int n = xy.length / 2;
    int minX = 0;
    int minY = 0;
    int maxX = 0;
    int maxY = 0;
    for (int i = 0; i < n; i++) {
      int x = xy[2 * i];
      int y = xy[2 * i + 1];
      minX = i == 0 ? x : Math.min(minX, x);
      minY = i == 0 ? y : Math.min(minY, y);
      maxX = i == 0 ? x : Math.max(maxX, x);
      maxY = i == 0 ? y : Math.max(maxY, y);
    }
    StringBuilder b = new StringBuilder();
    b.append("2D-Map\n").append(LABEL).append('\n');
    b.append(String.format(Locale.ROOT, "MinPos: %d %d\nMaxPos: %d %d\n", minX, minY, maxX, maxY));
    b.append("NumPoints: ").append(n).append('\n');
    b.append("PointsAreSorted: false\nResolution: ").append(CELL_MM).append('\n');
    b.append("DATA\n");
    w.write(b.toString());
    for (int i = 0; i < n; i++) {
      w.write(xy[2 * i] + " " + xy[2 * i + 1] + "\n");
    }
  }
}
