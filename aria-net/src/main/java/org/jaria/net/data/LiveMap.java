package org.jaria.net.data;

import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * The map a guiServer is building while a scan is logged ({@code "mappingLiveMap"}, a JAria data;
 * ArNetworking has none): what a monitor draws as the map grows. Thinned so it always fits one
 * packet: at most {@link #MAX_POINTS} points and {@link #MAX_PATH} poses of the path.
 *
 * @param status what the server is doing, for people ("scanning lab.2d", "built lab.map")
 * @param fileName the scan log being written or built ("" when none)
 * @param scans scans logged so far
 * @param points the map's points so far, mm, in the log's frame
 * @param path the path driven, mm, in the same frame
 * @param pose the robot's latest corrected pose, or null before the first scan
 */
public record LiveMap(
    String status, String fileName, long scans, Points points, Points path, ArPose pose)
    implements NetEncodable {

  /** Most points sent. */
  public static final int MAX_POINTS = 3000;

  /** Most poses of the path sent. */
  public static final int MAX_PATH = 400;

  private static final int FIELDS = 6;

  /** No scan running. */
  public static final LiveMap NONE = new LiveMap("", "", 0, Points.EMPTY, Points.EMPTY, null);

  /**
   * A live map from flat coordinates (x, y per point), thinned evenly to the limits.
   *
   * @param xy the points, x and y in turn, mm
   * @param pathXy the path, x and y in turn, mm
   */
  public static LiveMap of(
      String status, String fileName, long scans, int[] xy, int[] pathXy, ArPose pose) {
    return new LiveMap(
        status,
        fileName,
        scans,
        Points.ofFlat(thin(xy, MAX_POINTS), 2),
        Points.ofFlat(thin(pathXy, MAX_PATH), 2),
        pose);
  }

  /** Every k-th (x, y) pair so that at most {@code max} remain (the last pair always kept). */
  static int[] thin(int[] xy, int max) {
    int n = xy.length / 2;
    if (n <= max) {
      return xy.clone();
    }
    int[] out = new int[max * 2];
    for (int i = 0; i < max; i++) {
      int k = max == 1 ? n - 1 : (int) ((long) i * (n - 1) / (max - 1));
      out[2 * i] = xy[2 * k];
      out[2 * i + 1] = xy[2 * k + 1];
    }
    return out;
  }

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS).strToBuf(status).strToBuf(fileName).intToBuf(scans);
    points.write(out);
    path.write(out);
    Fields.writePose(out, pose);
  }

  /** Reads what {@link #write} wrote. */
  public static LiveMap read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "a live map");
    LiveMap m =
        new LiveMap(
            in.bufToStr(),
            in.bufToStr(),
            in.bufToLong(),
            Points.read(in),
            Points.read(in),
            Fields.readPose(in));
    Fields.end(in, n, FIELDS);
    return m;
  }
}
