package org.jaria.net.data;

import java.util.Objects;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;

/**
 * The planned path in the {@code getPath} layout: byte2 count, then byte4 x, byte4 y per point
 * (mm), robot to goal. ArNetworking's request reference says only "points representing planned
 * path"; the layout is ArNetworking's usual one for point lists (as {@code getSensorCurrent}), as
 * ARNL's source is not public. (JAria's fuller {@link PathSnapshot} is {@code getPathSnapshot}.)
 *
 * @param path the points
 */
public record PathPoints(Points path) implements NetEncodable {

  /** The most points the layout carries (a byte2 count). */
  public static final int MAX_POINTS = Short.MAX_VALUE;

  /** Checks the path is there and fits. */
  public PathPoints {
    Objects.requireNonNull(path, "path");
    if (path.size() > MAX_POINTS) {
      throw new IllegalArgumentException(
          "a path of " + path.size() + " points does not fit getPath's byte2 count");
    }
  }

  @Override
  public void write(ArNetPacket out) {
    out.byte2ToBuf(path.size());
    for (int i = 0; i < path.size(); i++) {
      out.byte4ToBuf(path.x(i)).byte4ToBuf(path.y(i));
    }
  }

  /**
   * Reads the layout.
   *
   * @throws ArNetPacketException if the count is negative or more than the packet holds
   */
  public static PathPoints read(ArNetPacket in) {
    int n = in.bufToByte2();
    if (n < 0 || (long) n * 8 > in.getRemaining()) {
      throw new ArNetPacketException(
          "getPath announces " + n + " points but has " + in.getRemaining() + " bytes");
    }
    int[] v = new int[n * 2];
    for (int i = 0; i < v.length; i++) {
      v[i] = in.bufToByte4();
    }
    return new PathPoints(Points.ofFlat(v, 2));
  }
}
