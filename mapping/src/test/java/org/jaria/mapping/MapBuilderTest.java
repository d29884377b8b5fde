package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

/**
 * Builds the fixed office log (recorded on the simulator with odometry error: along the corridor,
 * into a room and back past the start, so the way back closes a loop) and checks the map against
 * the true office and the path against the true laser poses.
 */
class MapBuilderTest {

  static final ArPose MOUNT = new ArPose(21, 0, 0);

  static String resource(String name) throws IOException {
    try (InputStream in = MapBuilderTest.class.getResourceAsStream(name)) {
      if (in == null) {
        throw new IOException("missing test resource " + name);
      }
      return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1);
    }
  }

  static List<ArPose> truth(String name) throws IOException {
    List<ArPose> out = new ArrayList<>();
    for (String line : resource(name).split("\n", -1)) {
      if (!line.startsWith("#") && !line.isBlank()) {
        String[] w = line.trim().split("\\s+", -1);
        out.add(
            new ArPose(
                Double.parseDouble(w[1]), Double.parseDouble(w[2]), Double.parseDouble(w[3])));
      }
    }
    return out;
  }

  static BuiltMap build(String log) throws IOException, MapBuildException {
    try (ScanLogReader r = new ScanLogReader(new StringReader(log), "test.2d")) {
      MapBuilder b = new MapBuilder(r.header(), MapBuilderParams.DEFAULTS);
      for (ScanLogEntry e = r.next(); e != null; e = r.next()) {
        b.add(e);
      }
      return b.finish();
    }
  }

  @Test
  void theOfficeLogBuildsAnAccurateMapAndPath() throws Exception {
    BuiltMap m = build(resource("office-room.2d"));
    List<ArPose> truth = truth("office-room.truth");
    MapQuality.PathError e = MapQuality.pathError(m, truth, MOUNT);
    assertTrue(e.rms() <= 30, "path RMS error " + e.rms() + " mm");
    assertTrue(e.max() <= 100, "path max error " + e.max() + " mm");
    double near =
        MapQuality.nearWalls(
            m, ArMap.loadBundled("office"), MapQuality.toTruth(m, truth, MOUNT), 50);
    assertTrue(near >= 0.95, "points within 50 mm of a true wall: " + near);
    assertTrue(m.stats().loopClosures() >= 1, m.stats().summary());
    assertTrue(m.lines().size() >= 8, "lines along the walls: " + m.lines().size());
    assertEquals(truth.size(), m.trajectory().size());
  }

  @Test
  void theMapKeepsTheLogsFrameAndItsStartAsHome() throws Exception {
    BuiltMap m = build(resource("office-room.2d"));
    ArMap map = m.toArMap();
    ArPose home = map.findHomePose().orElseThrow();
    assertEquals(m.trajectory().odometry(0), home);
    assertEquals(new ArPose(0, 0, 0), home, "the log starts at the odometry origin");
    assertEquals(20, map.getResolution());
    assertEquals(m.pointCount(), map.getPoints().size());
    assertTrue(map.getPoints().isSorted());
  }

  @Test
  void goalsLoggedOnTheWayBecomeGoalsOfTheMap() throws Exception {
    String log = resource("office-room.2d");
    // a goal placed 30 s into the drive, as ArLaserLogger writes it
    int at = log.indexOf("logTime: 30.");
    int block = log.lastIndexOf("logTime:", at - 1);
    String goal =
        """
        time: 30.000
        robot: 5000 0 0.00
        robotGlobal: 5000 0 0.00
        cairn: GoalWithHeading "" ICON_GOALWITHHEADING "goal1"
        """;
    BuiltMap m = build(log.substring(0, block) + goal + log.substring(block));
    ArMapObject g = m.toArMap().findMapObject("goal1").orElseThrow();
    assertEquals("GoalWithHeading", g.type());
    // where odometry said, corrected by the matching (a few cm at most this early)
    assertTrue(g.pose().findDistanceTo(new ArPose(5000, 0, 0)) < 150, g.toString());
  }

  @Test
  void aLogThatNeverMovedIsAClearError() throws Exception {
    String log = resource("office-room.2d");
    int second = log.indexOf("logTime:", log.indexOf("scan1:"));
    MapBuildException one =
        assertThrows(MapBuildException.class, () -> build(log.substring(0, second)));
    assertTrue(one.getMessage().contains("never moved"), one.getMessage());
    assertTrue(one.getMessage().contains("1 scan,"), one.getMessage());
    String first = log.substring(log.indexOf("logTime:"), second);
    String still = log.substring(0, second) + first.repeat(20);
    MapBuildException many = assertThrows(MapBuildException.class, () -> build(still));
    assertTrue(many.getMessage().contains("21 scans"), many.getMessage());
  }

  @Test
  void aLogWithoutLaserScansIsAClearError() throws Exception {
    String log = resource("office-room.2d");
    String header = log.substring(0, log.indexOf("logTime:"));
    MapBuildException e = assertThrows(MapBuildException.class, () -> build(header));
    assertTrue(e.getMessage().contains("no laser scans"), e.getMessage());
    // scans whose readings all say "no echo"
    String empty = log.replaceAll("scan1: .*", "scan1: 0 0  0 0  0 0  ");
    MapBuildException none = assertThrows(MapBuildException.class, () -> build(empty));
    assertTrue(none.getMessage().contains("enough laser readings"), none.getMessage());
  }

  @Test
  void readingsAtALasersNoEchoRangeAreDropped() throws Exception {
    // as an LMS-200 in millimetre mode logs it: whatever lies beyond 8183 mm reads 8183 mm
    String log = resource("office-room.2d");
    StringBuilder sb = new StringBuilder();
    long phantoms = 0;
    for (String line : log.split("\n", -1)) {
      if (!line.startsWith("scan1:")) {
        sb.append(line).append('\n');
        continue;
      }
      sb.append("scan1: ");
      String[] w = line.substring(7).trim().split("\\s+", -1);
      for (int i = 0; i + 1 < w.length; i += 2) {
        double x = Double.parseDouble(w[i]);
        double y = Double.parseDouble(w[i + 1]);
        double r = Math.hypot(x, y);
        if (r > 8183) {
          x = x * 8183 / r;
          y = y * 8183 / r;
          phantoms++;
        }
        sb.append(Math.round(x)).append(' ').append(Math.round(y)).append("  ");
      }
      sb.append('\n');
    }
    BuiltMap m = build(sb.toString());
    assertTrue(phantoms > 1000, "the log has phantom readings: " + phantoms);
    assertTrue(m.stats().noEchoReadings() >= phantoms * 9 / 10, m.stats().summary());
    assertEquals(8183, m.stats().noEchoRange(), 2);
    List<ArPose> truth = truth("office-room.truth");
    double near =
        MapQuality.nearWalls(
            m, ArMap.loadBundled("office"), MapQuality.toTruth(m, truth, MOUNT), 50);
    assertTrue(near >= 0.95, "no phantom circle in the map: " + near);
  }
}
