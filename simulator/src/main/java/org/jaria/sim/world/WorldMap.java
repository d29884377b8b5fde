package org.jaria.sim.world;

import java.util.Collection;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;

/**
 * The physical part of a map, as the simulator uses it: wall lines, sensor points (small discs of
 * half the map resolution) and where robots start. Forbidden lines and areas are not physical and
 * are not here.
 *
 * @param source where the map came from (file name or description)
 * @param lines the LINES entries
 * @param pointX x of the DATA points
 * @param pointY y of the DATA points
 * @param pointRadius radius each point blocks, mm
 * @param home where robots start (first RobotHome, else Dock, else the origin)
 */
// The arrays are copied in and out.
@SuppressWarnings("ArrayRecordComponent")
public record WorldMap(
    String source,
    List<ArLineSegment> lines,
    int[] pointX,
    int[] pointY,
    double pointRadius,
    ArPose home) {

  /** An empty world: no walls, robots start at the origin. */
  public static final WorldMap EMPTY =
      new WorldMap("empty", List.of(), new int[0], new int[0], 10, ArPose.ORIGIN);

  /** Checks and copies. */
  public WorldMap {
    if (pointX.length != pointY.length) {
      throw new IllegalArgumentException(
          pointX.length + " point x values but " + pointY.length + " y values");
    }
    lines = List.copyOf(lines);
    pointX = pointX.clone();
    pointY = pointY.clone();
    if (!(pointRadius > 0)) {
      pointRadius = 10;
    }
    if (home == null) {
      home = ArPose.ORIGIN;
    }
  }

  /** A map made of wall lines only. */
  public static WorldMap ofLines(String source, List<ArLineSegment> lines, ArPose home) {
    return new WorldMap(source, lines, new int[0], new int[0], 10, home);
  }

  @Override
  public int[] pointX() {
    return pointX.clone();
  }

  @Override
  public int[] pointY() {
    return pointY.clone();
  }

  /** Number of DATA points. */
  public int pointCount() {
    return pointX.length;
  }

  /** Whether the map has anything solid. */
  public boolean isEmpty() {
    return lines.isEmpty() && pointX.length == 0;
  }

  /** Builds the spatial index of this map plus {@code obstacles} (lists of segments). */
  public SegmentIndex buildIndex(Collection<? extends List<ArLineSegment>> obstacles) {
    SegmentIndex.Builder b = SegmentIndex.builder();
    for (ArLineSegment s : lines) {
      b.addSegment(s.x1(), s.y1(), s.x2(), s.y2(), RayHit.HitKind.LINE);
    }
    for (int i = 0; i < pointX.length; i++) {
      b.addDisc(pointX[i], pointY[i], pointRadius, RayHit.HitKind.POINT);
    }
    for (List<ArLineSegment> o : obstacles) {
      for (ArLineSegment s : o) {
        b.addSegment(s.x1(), s.y1(), s.x2(), s.y2(), RayHit.HitKind.OBSTACLE);
      }
    }
    return b.build();
  }
}
