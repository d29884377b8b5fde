package org.jaria.mapping;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapFormatException;

/**
 * A map built from a scan log: points thinned to the resolution, lines along the walls, the robot's
 * start as RobotHome and the goals logged on the way, in the log's own frame; plus the corrected
 * path and what the build did ({@link Stats}). {@link #writeFile} writes an ARIA {@code .map}
 * ({@link MapFileWriter}); {@link #toArMap()} gives it as an {@link ArMap} for localization, path
 * planning or the editor.
 */
public final class BuiltMap {

  /**
   * What a build did.
   *
   * @param scansRead scans in the log
   * @param scansUsed scans matched into the map
   * @param stationary scans taken while the robot stood (not matched again)
   * @param sparse scans with too few readings to match (placed by odometry)
   * @param matchFailures scans whose match was not convincing (placed by odometry)
   * @param poses poses of the graph
   * @param loopClosures loop closure edges
   * @param loopsRejected loop closure attempts whose match was not convincing, and loop edges
   *     dropped because they disagreed with the rest
   * @param optimizations graph optimisations
   * @param prunedPoses poses whose points were let go (an older pose shows the same place)
   * @param noEchoReadings readings dropped at the laser's no-echo range
   * @param noEchoRange the no-echo range found (mm), infinity if none
   * @param noisePoints map cells dropped as lone readings
   */
  public record Stats(
      long scansRead,
      long scansUsed,
      long stationary,
      long sparse,
      long matchFailures,
      int poses,
      int loopClosures,
      int loopsRejected,
      int optimizations,
      long prunedPoses,
      long noEchoReadings,
      double noEchoRange,
      long noisePoints) {

    Stats(
        long scansRead,
        long scansUsed,
        long stationary,
        long sparse,
        long matchFailures,
        int poses,
        int loopClosures,
        int loopsRejected,
        int optimizations,
        long prunedPoses,
        long noEchoReadings,
        double noEchoRange) {
      this(
          scansRead,
          scansUsed,
          stationary,
          sparse,
          matchFailures,
          poses,
          loopClosures,
          loopsRejected,
          optimizations,
          prunedPoses,
          noEchoReadings,
          noEchoRange,
          0);
    }

    Stats withNoise(long n) {
      return new Stats(
          scansRead,
          scansUsed,
          stationary,
          sparse,
          matchFailures,
          poses,
          loopClosures,
          loopsRejected,
          optimizations,
          prunedPoses,
          noEchoReadings,
          noEchoRange,
          n);
    }

    /** A one-line summary. */
    public String summary() {
      return String.format(
          Locale.ROOT,
          "%d scans (%d matched, %d standing, %d sparse, %d by odometry), %d poses, %d loop"
              + " closures (%d rejected), %d optimisations%s",
          scansRead,
          scansUsed,
          stationary,
          sparse,
          matchFailures,
          poses,
          loopClosures,
          loopsRejected,
          optimizations,
          noEchoReadings > 0
              ? String.format(
                  Locale.ROOT,
                  ", %d no-echo readings at %.0f mm dropped",
                  noEchoReadings,
                  noEchoRange)
              : "");
    }
  }

  private final int[] xs;
  private final int[] ys;
  private final List<ArLineSegment> lines;
  private final List<ArMapObject> objects;
  private final int resolution;
  private final Trajectory trajectory;
  private final Stats stats;

  BuiltMap(
      int[] xs,
      int[] ys,
      List<ArLineSegment> lines,
      List<ArMapObject> objects,
      int resolution,
      Trajectory trajectory,
      Stats stats) {
    this.xs = xs;
    this.ys = ys;
    this.lines = List.copyOf(lines);
    this.objects = List.copyOf(objects);
    this.resolution = resolution;
    this.trajectory = trajectory;
    this.stats = stats;
  }

  /** Number of map points. */
  public int pointCount() {
    return xs.length;
  }

  /** X of point {@code i} (sorted by x, then y), mm. */
  public int x(int i) {
    return xs[i];
  }

  /** Y of point {@code i}, mm. */
  public int y(int i) {
    return ys[i];
  }

  /** The walls' lines. */
  public List<ArLineSegment> lines() {
    return lines;
  }

  /** RobotHome first, then the logged goals. */
  public List<ArMapObject> objects() {
    return objects;
  }

  /** The points' spacing, mm. */
  public int resolution() {
    return resolution;
  }

  /** The corrected path. */
  public Trajectory trajectory() {
    return trajectory;
  }

  /** What the build did. */
  public Stats stats() {
    return stats;
  }

  /** Writes the map as an ARIA {@code .map} file. */
  public void writeFile(Path file) throws IOException {
    try (Writer w = Files.newBufferedWriter(file, StandardCharsets.ISO_8859_1)) {
      MapFileWriter.write(this, w);
    }
  }

  /** The map as an {@link ArMap} (as if written and read back). */
  public ArMap toArMap() {
    StringWriter w = new StringWriter();
    try {
      MapFileWriter.write(this, w);
      return ArMap.read(new StringReader(w.toString()), "built map");
    } catch (MapFormatException e) {
      throw new IllegalStateException("the built map does not read back: " + e.getMessage(), e);
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
  }
}
