package org.jaria.net.server.info;

import org.jaria.net.data.PathPoints;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;

/**
 * The path planner's state for clients (ARNL's {@code ArServerInfoPath}): {@code "getPath"}, the
 * planned path in ARNL's layout ({@link PathPoints}); and, with {@link #addPathSnapshot}, JAria's
 * {@code "getPathSnapshot"} — state, status, goal, path and the local search area ({@link
 * PathSnapshot}). Both are published, polled from the planner.
 */
public final class ArServerInfoPath {

  private final ArServerBase server;
  private final PathPlanningInfo planner;

  /** Registers {@code "getPath"} with {@code server}. */
  public ArServerInfoPath(ArServerBase server, PathPlanningInfo planner) {
    this.server = server;
    this.planner = planner;
    server.addPublishedData(
        "getPath",
        "gets the path the robot is following",
        "byte2: numPoints; repeating numPoints times: byte4: x; byte4: y",
        "PathInfo",
        PolledPublication.of(() -> new PathPoints(clip(planner.getPathState()))));
  }

  /** Registers JAria's {@code "getPathSnapshot"} (after the server's other data). */
  public void addPathSnapshot() {
    server.addPublishedData(
        "getPathSnapshot",
        "JAria: the planner's state, status, goal, planned path and local search area",
        "PathSnapshot [state, status, goal or nil, path points, search area points]",
        "PathInfo",
        PolledPublication.of(planner::getPathState));
  }

  private static org.jaria.net.data.Points clip(PathSnapshot s) {
    org.jaria.net.data.Points p = s.path();
    if (p.size() <= PathPoints.MAX_POINTS) {
      return p;
    }
    int[] v = new int[PathPoints.MAX_POINTS * 2];
    for (int i = 0; i < PathPoints.MAX_POINTS; i++) {
      v[2 * i] = p.x(i);
      v[2 * i + 1] = p.y(i);
    }
    return org.jaria.net.data.Points.ofFlat(v, 2);
  }
}
