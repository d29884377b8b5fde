package org.jaria.laser.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.List;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

/** Reading logs as ARIA writes them, old and new, and every kind of damaged log. */
class ScanLogReaderTest {

  static final String HEADER =
      """
      LaserOdometryLog
      #Created by ArLaserLogger
      version: 4
      sick1pose: 18 0 0.00
      sick1conf: -90.00 90.00 3
      sick1name: sim_lms2xx_1
      scan1pose: 18 0 0 0.00
      scan1conf: -90.00 90.00 3
      scan1name: sim_lms2xx_1
      locationTypes: robot robotGlobal
      """;

  static String scan(int id, double t, int x, String readings) {
    return "logTime: "
        + t
        + "\nvelocities: 0.00 0.00 0.00\nscanId: "
        + id
        + "\nrobot: "
        + x
        + " 0 0.00\nrobotGlobal: "
        + x
        + " 0 0.00\nscan1: "
        + readings
        + "\n";
  }

  private static ScanLogReader reader(String text) throws IOException {
    return new ScanLogReader(new StringReader(text), "lab.2d");
  }

  @Test
  void readsHeaderScansAndGoals() throws IOException {
    String log =
        HEADER
            + scan(0, 0.09, 0, "0 -956  17 -958  0 0  ")
            + "time: 1.000\nrobot: 5 6 90.00\nrobotGlobal: 5 6 90.00\n"
            + "cairn: GoalWithHeading \"\" ICON_GOALWITHHEADING \"goal1\"\n"
            + scan(1, 1.59, 326, "1 2  3 4  5 6  ")
            + "# End of log\n";
    try (ScanLogReader r = reader(log)) {
      ScanLogHeader h = r.header();
      assertEquals(4, h.version());
      assertEquals(new ArPose(18, 0, 0), h.laserPose());
      assertEquals(3, h.readingCount());
      assertEquals(90.0, h.increment());
      assertEquals("sim_lms2xx_1", h.laserName());
      List<ScanLogEntry> all = r.readAll();
      assertEquals(3, all.size());
      LoggedScan s0 = assertInstanceOf(LoggedScan.class, all.get(0));
      assertEquals(3, s0.size());
      assertEquals(2, s0.echoCount());
      assertFalse(s0.hasEcho(2));
      assertEquals(-958, s0.y(1));
      LogTag goal = assertInstanceOf(LogTag.class, all.get(1));
      assertTrue(goal.isCairn());
      assertEquals("GoalWithHeading", goal.cairnType());
      assertEquals("goal1", goal.cairnName());
      assertEquals(new ArPose(5, 6, 90), goal.robotPose());
      LoggedScan s1 = assertInstanceOf(LoggedScan.class, all.get(2));
      assertEquals(1, s1.id());
      assertEquals(new ArPose(326, 0, 0), s1.robotPose());
      assertTrue(r.stats().endMarker());
      assertEquals("", r.stats().skippedSummary());
    }
  }

  @Test
  void readsOldLogsWithRangesAndTime() throws IOException {
    String log =
        """
        LaserOdometryLog
        #Created by ARIA's ArSickLogger
        version: 1
        sick1pose: 0 0 0.00
        sick1conf: -90 90 3
        time: 0.5
        robot: 10 20 0.00 0 0
        sick1: 1000 0 2000
        """;
    try (ScanLogReader r = reader(log)) {
      LoggedScan s = assertInstanceOf(LoggedScan.class, r.next());
      assertEquals(0, s.x(0), 1e-9);
      assertEquals(-1000, s.y(0), 1e-9);
      assertFalse(s.hasEcho(1));
      assertEquals(2000, s.y(2), 1e-9);
      assertEquals(0.5, s.time());
      assertNull(r.next());
    }
  }

  @Test
  void bothFormsOfOneSweepCountOnce() throws IOException {
    String log =
        HEADER
            + "logTime: 0.1\nvelocities: 0 0 0\nscanId: 0\nrobot: 0 0 0\n"
            + "sick1: 1000 1000 1000\nscan1: 0 -1000  1000 0  0 1000  \n";
    try (ScanLogReader r = reader(log)) {
      assertEquals(1, r.readAll().size());
      assertEquals(1, r.stats().ignoredLines());
    }
  }

  @Test
  void aFileThatIsNoLogSaysSo() {
    ScanLogFormatException e =
        assertThrows(ScanLogFormatException.class, () -> reader("2D-Map\nMinPos: 0 0\n"));
    assertTrue(e.getMessage().contains("lab.2d line 1"), e.getMessage());
    assertTrue(e.getMessage().contains("LaserOdometryLog"), e.getMessage());
    assertThrows(ScanLogFormatException.class, () -> reader(""));
  }

  @Test
  void aBrokenLineNamesItsLineAndWhatWasExpected() throws IOException {
    String log = HEADER + scan(0, 0.1, 0, "1 2  3 4  5 6  ").replace("robot: 0 0", "robot: 0 abc");
    try (ScanLogReader r = reader(log)) {
      ScanLogFormatException e = assertThrows(ScanLogFormatException.class, r::next);
      assertEquals(14, e.line());
      assertTrue(e.getMessage().contains("robot: needs X Y TH"), e.getMessage());
      assertTrue(e.getMessage().contains("'abc'"), e.getMessage());
    }
  }

  @Test
  void anOddNumberOfCoordinatesIsAnError() throws IOException {
    try (ScanLogReader r = reader(HEADER + scan(0, 0.1, 0, "1 2  3"))) {
      ScanLogFormatException e = assertThrows(ScanLogFormatException.class, r::next);
      assertTrue(e.getMessage().contains("odd number"), e.getMessage());
    }
  }

  @Test
  void readingsBeforeAnyPoseAreAnError() throws IOException {
    try (ScanLogReader r = reader(HEADER + "logTime: 0.1\nscan1: 1 2  \n")) {
      ScanLogFormatException e = assertThrows(ScanLogFormatException.class, r::next);
      assertTrue(e.getMessage().contains("without a robot: pose"), e.getMessage());
    }
  }

  @Test
  void nanInfAndHugeReadingsAreCountedAsNoEcho() throws IOException {
    try (ScanLogReader r = reader(HEADER + scan(0, 0.1, 0, "nan 5  -inf 3  1e9 1  7 8  "))) {
      LoggedScan s = assertInstanceOf(LoggedScan.class, r.next());
      assertEquals(4, s.size());
      assertEquals(1, s.echoCount());
      assertEquals(3, r.stats().badReadings());
    }
  }

  @Test
  void aScanWithADamagedPoseIsSkippedAndCounted() throws IOException {
    String log =
        HEADER
            + scan(0, 0.1, 0, "1 2  ").replace("robot: 0 0", "robot: nan 0")
            + scan(1, 0.2, 5, "3 4  ");
    try (ScanLogReader r = reader(log)) {
      LoggedScan s = assertInstanceOf(LoggedScan.class, r.next());
      assertEquals(1, s.id());
      assertEquals(1, r.stats().badPoseScans());
    }
  }

  @Test
  void timeGoingBackwardsIsCountedAndKept() throws IOException {
    String log = HEADER + scan(0, 5.0, 0, "1 2  ") + scan(1, 2.0, 5, "3 4  ");
    try (ScanLogReader r = reader(log)) {
      assertEquals(2, r.readAll().size());
      assertEquals(1, r.stats().timeBackwards());
    }
  }

  @Test
  void aLogCutOffMidScanKeepsWhatCameBefore() throws IOException {
    String whole = HEADER + scan(0, 0.1, 0, "1 2  3 4  ") + scan(1, 0.2, 5, "5 6  7 8  ");
    // cut inside the last readings line (no line feed after it), and inside the last block
    for (String cut :
        List.of(
            whole.substring(0, whole.length() - 4),
            whole.substring(0, whole.indexOf("scanId: 1")))) {
      try (ScanLogReader r = reader(cut)) {
        assertEquals(1, r.readAll().size(), cut);
        assertEquals(1, r.stats().truncatedScans(), cut);
        assertFalse(r.stats().endMarker());
      }
    }
  }

  @Test
  void otherLasersAndUnknownTagsAreSkipped() throws IOException {
    String log =
        HEADER
            + "loop: start 1\n"
            + scan(0, 0.1, 0, "1 2  ").replace("scan1:", "scan2:")
            + scan(1, 0.2, 0, "1 2  ")
                .replace("robotGlobal", "robotRaw: 1 2 3\nfoo: bar\nrobotGlobal");
    try (ScanLogReader r = reader(log)) {
      assertEquals(1, r.readAll().size());
      assertEquals(1, r.stats().otherLaserScans());
      assertEquals(1, r.stats().ignoredLines()); // foo: (robotRaw: is a known part of a scan)
    }
  }

  @Test
  void binaryDataAndEndlessLinesAreErrorsNotMemory() throws IOException {
    String binary = HEADER + scan(0, 0.1, 0, "1 2  ") + "scan1: \u0000\u0001\n";
    try (ScanLogReader r = reader(binary)) {
      r.next();
      ScanLogFormatException e = assertThrows(ScanLogFormatException.class, r::next);
      assertTrue(e.getMessage().contains("control character"), e.getMessage());
    }
    String endless =
        HEADER + scan(0, 0.1, 0, "1 2  ") + "scan1: " + "1 ".repeat(LogLines.MAX_LINE / 2 + 10);
    try (ScanLogReader r = reader(endless)) {
      r.next();
      ScanLogFormatException e = assertThrows(ScanLogFormatException.class, r::next);
      assertTrue(e.getMessage().contains("longer than"), e.getMessage());
    }
  }

  @Test
  void numbersParseAsCPrintfWritesThem() throws IOException {
    LogLines l =
        new LogLines(new StringReader("x: 12 -3.25 1e3 +0.5 .5 -0 nan -nan inf 7.000001\n"), "t");
    assertTrue(l.next());
    l.tagLength();
    double[] want = {12, -3.25, 1000, 0.5, 0.5, -0.0, Double.NaN, Double.NaN, Double.NaN, 7.000001};
    for (double w : want) {
      assertEquals(w, l.number("a number"), 0);
    }
    assertFalse(l.hasMore());
  }
}
