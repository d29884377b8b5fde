package org.jaria.net.data;

import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * What the path planner is doing ({@code "getPath"}).
 *
 * @param state the planner's state, e.g. "NOT_INITIALIZED", "PLANNING_PATH", "MOVING_TO_GOAL",
 *     "REACHED_GOAL", "FAILED_PLAN"
 * @param status a sentence for people ("Going to goal A")
 * @param goal the current goal, or null
 * @param path the planned path, robot to goal
 * @param searchArea the local planner's search area (a closed polygon), or empty
 */
public record PathSnapshot(String state, String status, ArPose goal, Points path, Points searchArea)
    implements NetEncodable {

  private static final int FIELDS = 5;

  /** Nothing planned. */
  public static final PathSnapshot IDLE =
      new PathSnapshot("IDLE", "", null, Points.EMPTY, Points.EMPTY);

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS).strToBuf(state).strToBuf(status);
    Fields.writePose(out, goal);
    path.write(out);
    searchArea.write(out);
  }

  /** Reads what {@link #write} wrote. */
  public static PathSnapshot read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "a path");
    PathSnapshot p =
        new PathSnapshot(
            in.bufToStr(), in.bufToStr(), Fields.readPose(in), Points.read(in), Points.read(in));
    Fields.end(in, n, FIELDS);
    return p;
  }
}
