package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.util.List;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogHeader;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMap;
import org.jaria.sim.OdometryError;
import org.junit.jupiter.api.Test;

/**
 * ArLaserLogger on a simulated robot: ARIA's header, a scan every 300 mm or 25 degrees with the
 * odometry pose it was taken at, no echo written as {@code 0 0}, and the end marker.
 */
class ArLaserLoggerTest {

  @Test
  void logsAsSickLoggerDoes() throws Exception {
    ArMap hall = ArMap.loadBundled("hall");
    ArPose home = hall.findHomePose().orElseThrow();
    List<ArPose> route =
        List.of(
            new ArPose(home.x() + 3000, home.y()), new ArPose(home.x() + 3000, home.y() + 2000));
    SimDrive.Result r = SimDrive.record(hall, 5, OdometryError.NONE, home, route, 400);
    assertEquals(0, r.mismatched(), "each logged sweep is the simulator's sweep of that moment");
    assertTrue(r.log().endsWith("# End of log\n"));
    try (ScanLogReader reader = new ScanLogReader(new StringReader(r.log()), "hall")) {
      ScanLogHeader h = reader.header();
      assertEquals(ScanLogHeader.ARIA_VERSION, h.version());
      assertEquals(new ArPose(21, 0, 0), h.laserPose(), "the robot's parameter file's LaserX");
      assertEquals(181, h.readingCount());
      assertEquals(-90, h.firstAngle());
      List<ScanLogEntry> all = reader.readAll();
      assertEquals(r.truth().size(), all.size());
      LoggedScan prev = null;
      for (ScanLogEntry e : all) {
        LoggedScan s = (LoggedScan) e;
        assertEquals(181, s.size());
        for (int k = 0; k < s.size(); k++) {
          assertTrue(s.range(k) < 31000, "no phantom at the laser's 32 m limit: " + s.range(k));
        }
        if (prev != null) {
          double moved = prev.robotPose().findDistanceTo(s.robotPose());
          double turned = Math.abs(ArMath.subAngle(prev.robotPose().th(), s.robotPose().th()));
          assertTrue(moved > 250 || turned > 20, "logged after moving: " + moved + ", " + turned);
          assertTrue(s.time() > prev.time());
        }
        // without odometry error the logged pose plus the mounting is the true laser pose,
        // up to the 21 mm by which the simulator's laser sits behind the parameter file's
        ArPose laser = Poses.compose(s.robotPose(), h.laserPose());
        ArPose truth = Poses.compose(home, Poses.inverse(((LoggedScan) all.get(0)).robotPose()));
        assertTrue(
            Poses.compose(truth, laser).findDistanceTo(r.truth().get(s.id())) < 30,
            "scan " + s.id());
        prev = s;
      }
      assertTrue(all.size() >= 15, "scans: " + all.size());
    }
  }
}
