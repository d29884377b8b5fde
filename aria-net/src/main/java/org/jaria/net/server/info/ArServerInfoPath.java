package org.jaria.net.server.info;

import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;

/**
 * The path planner's state for clients (ArNetworking's {@code ArServerInfoPath}): {@code
 * "getPath"}, published — state, status, goal, the planned path and the local search area.
 */
public final class ArServerInfoPath {

  /** Registers {@code "getPath"} with {@code server}. */
  public ArServerInfoPath(ArServerBase server, PathPlanningInfo planner) {
    server.addPublishedData(
        "getPath",
        "the planned path, goal and local search area",
        "PathSnapshot [state, status, goal or nil, path points, search area points]",
        "PathInfo",
        PolledPublication.of(planner::getPathState));
  }
}
