package org.jaria.laser.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.List;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

/** The writer's lines are ARIA's {@code ArLaserLogger}'s, character for character. */
class ScanLogWriterTest {

  private static String write(ScanLogHeader h, ScanLogEntry... entries) throws IOException {
    StringWriter out = new StringWriter();
    try (ScanLogWriter w = new ScanLogWriter(out)) {
      w.writeHeader(h);
      for (ScanLogEntry e : entries) {
        w.write(e);
      }
    }
    return out.toString();
  }

  @Test
  void headerScanAndGoalAreWrittenAsArLaserLoggerWritesThem() throws IOException {
    ScanLogHeader h = ScanLogHeader.of(new ArPose(21, 0, 0), -90, 90, 3, "lms2xx_1");
    LoggedScan s =
        new LoggedScan(
            0,
            1.5906,
            450,
            -2.125,
            0,
            new ArPose(326.4, -0.5, 1.005),
            new ArPose(326.4, -0.5, 1.005),
            new double[] {0, 1000.5, 2.5},
            new double[] {-956.4, 0, 0});
    LogTag goal =
        new LogTag(
            2.25,
            new ArPose(400, 10, 90),
            null,
            "cairn: GoalWithHeading \"\" ICON_GOALWITHHEADING \"goal1\"");
    assertEquals(
        """
        LaserOdometryLog
        #Created by ArLaserLogger
        version: 4
        sick1pose: 21 0 0.00
        sick1conf: -90.00 90.00 3
        sick1name: lms2xx_1
        scan1pose: 21 0 0 0.00
        scan1conf: -90.00 90.00 3
        scan1name: lms2xx_1
        locationTypes: robot robotGlobal
        logTime: 1.591
        velocities: 450.00 -2.12 0.00
        scanId: 0
        robot: 326 -0 1.00
        robotGlobal: 326 -0 1.00
        scan1: 0 -956  1000 0  2 0 \s
        time: 2.250
        robot: 400 10 90.00
        robotGlobal: 400 10 90.00
        cairn: GoalWithHeading "" ICON_GOALWITHHEADING "goal1"
        # End of log
        """,
        write(h, s, goal));
  }

  @Test
  void readingsWithoutEchoAreWrittenAsZeroPairs() throws IOException {
    ScanLogHeader h = ScanLogHeader.of(ArPose.ORIGIN, -1, 1, 3, "l");
    LoggedScan s =
        new LoggedScan(
            7,
            0,
            0,
            0,
            0,
            ArPose.ORIGIN,
            null,
            new double[] {Double.NaN, 0, 5},
            new double[] {1, 0, 5});
    String text = write(h, s);
    assertEquals(true, text.contains("scan1: 0 0  0 0  5 5  \n"), text);
  }

  @Test
  void whatIsWrittenReadsBackEqual() throws IOException {
    ScanLogHeader h = ScanLogHeader.of(new ArPose(160, 7, 0), -90, 90, 2, "sim_lms2xx_1");
    LoggedScan a =
        new LoggedScan(
            0,
            0.1,
            0,
            0,
            0,
            new ArPose(1, 2, 3),
            new ArPose(4, 5, 6),
            new double[] {1, 2},
            new double[] {3, 4});
    LoggedScan b =
        new LoggedScan(
            1,
            0.4,
            100,
            5,
            0,
            new ArPose(301, 2, 3),
            new ArPose(304, 5, 6),
            new double[] {7, 8},
            new double[] {-3, 4});
    String text = write(h, a, b);
    try (ScanLogReader r = new ScanLogReader(new StringReader(text), "t")) {
      assertEquals(h, r.header());
      assertEquals(List.of(a, b), r.readAll());
      assertEquals(true, r.stats().endMarker());
    }
  }

  @Test
  void aScanBeforeTheHeaderIsRefused() {
    ScanLogWriter w = new ScanLogWriter(new StringWriter());
    LoggedScan s = new LoggedScan(0, 0, 0, 0, 0, ArPose.ORIGIN, null, new double[0], new double[0]);
    assertThrows(IllegalStateException.class, () -> w.writeScan(s));
  }
}
