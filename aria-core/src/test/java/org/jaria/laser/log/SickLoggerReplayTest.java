package org.jaria.laser.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.util.List;
import org.jaria.geom.ArPose;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Logs written by ARIA's own sickLogger (AriaCoda), recorded while it was driven by its arrow keys
 * in the office, once against {@code jaria sim} and once against AMRISim, with a goal placed on the
 * way ({@code g}). The bytes are replayed here as they were written.
 */
class SickLoggerReplayTest {

  @ParameterizedTest
  @CsvSource({"sicklogger-jaria-sim.2d, 27", "sicklogger-amrisim.2d, 51"})
  void realSickLoggerLogsRead(String file, int scans) throws IOException {
    try (InputStream in = getClass().getResourceAsStream(file);
        ScanLogReader r = ScanLogReader.of(in, file)) {
      ScanLogHeader h = r.header();
      assertEquals(4, h.version());
      assertEquals(new ArPose(21, 0, 0), h.laserPose());
      assertEquals(-90, h.firstAngle());
      assertEquals(90, h.lastAngle());
      assertEquals(361, h.readingCount(), "sickLogger asks for half-degree readings");
      assertEquals("sim_lms2xx_1", h.laserName());
      assertEquals(List.of("robot", "robotGlobal"), h.locationTypes());
      List<ScanLogEntry> all = r.readAll();
      List<LoggedScan> logged =
          all.stream().filter(LoggedScan.class::isInstance).map(LoggedScan.class::cast).toList();
      assertEquals(scans, logged.size());
      for (int i = 0; i < logged.size(); i++) {
        LoggedScan s = logged.get(i);
        assertEquals(i, s.id());
        assertEquals(361, s.size());
        assertTrue(s.echoCount() > 100, "scan " + i + " has echoes");
        for (int k = 0; k < s.size(); k++) {
          // ARIA wrote no-echo beams as 0 0: nothing at the simulated laser's 32 m limit
          assertTrue(s.range(k) < 31000, "reading " + k + " of scan " + i + ": " + s.range(k));
        }
      }
      // the first reading points to the robot's right (-90 degrees), as a wall 0.95 m away
      LoggedScan first = logged.get(0);
      assertEquals(0, first.x(0), 10);
      assertTrue(first.y(0) < -900 && first.y(0) > -1000, "y " + first.y(0));
      assertEquals(new ArPose(0, 0, 0), first.robotPose());
      LogTag goal =
          all.stream().filter(LogTag.class::isInstance).map(LogTag.class::cast).findFirst().get();
      assertEquals("goal1", goal.cairnName());
      assertEquals("GoalWithHeading", goal.cairnType());
      assertInstanceOf(ArPose.class, goal.global().orElseThrow());
      assertFalse(r.stats().endMarker(), "sickLogger was stopped with Escape");
      assertEquals(0, r.stats().truncatedScans());
      assertEquals("", r.stats().skippedSummary());
    }
  }
}
