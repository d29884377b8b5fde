package org.jaria.laser.log;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import org.jaria.geom.ArPose;

/**
 * Reads a laser scan log ({@code .2d}) one entry at a time, as {@code sickLogger}, ARIA's {@code
 * ArLaserLogger} or JAria's write it: memory stays that of one scan however long the log is.
 *
 * <pre>{@code
 * try (ScanLogReader r = ScanLogReader.open(Path.of("lab.2d"))) {
 *   ScanLogHeader h = r.header();
 *   for (ScanLogEntry e = r.next(); e != null; e = r.next()) {
 *     if (e instanceof LoggedScan s) { ... }
 *   }
 *   System.out.println(r.stats().skippedSummary());
 * }
 * }</pre>
 *
 * <p>What is wrong in a log is either an error that names the line and what was expected ({@link
 * ScanLogFormatException}: a value that is no number, a scan with an odd number of coordinates, a
 * scan before any robot pose, binary data, a line of megabytes) or a counted skip ({@link
 * #stats()}: {@code nan} and {@code inf} readings, a damaged pose, time going backwards, a scan cut
 * off by the end of the file, a second laser's scans, unknown tags). Tags the reader does not know
 * are ignored, as ARIA's documentation of the format asks.
 *
 * <p>Not thread-safe: one thread reads.
 */
public final class ScanLogReader implements AutoCloseable {

  /** A reading farther than this (1 km) is damaged, not measured. */
  static final double MAX_READING = 1e6;

  /** A pose farther than this (1000 km) from the origin is damaged. */
  static final double MAX_POSE = 1e9;

  private final LogLines lines;
  private final Reader in;
  private final String source;
  private ScanLogHeader header;
  private boolean held;
  private boolean done;

  // The block being read: fields seen since its time line.
  private double time = 0;
  private double vel;
  private double rotVel;
  private double latVel;
  private int scanId = -1;
  private boolean blockHasScan;
  private boolean tagBlock;
  private boolean blockOpen;
  private int scansRead;
  private ArPose robot;
  private ArPose global;
  private double lastTime = Double.NEGATIVE_INFINITY;

  private long scans;
  private long tags;
  private long readings;
  private long badReadings;
  private long badPoseScans;
  private long timeBackwards;
  private long truncated;
  private long otherLasers;
  private long ignored;
  private boolean endMarker;
  private double[] xs = new double[1024];
  private double[] ys = new double[1024];

  /**
   * A reader of {@code in}; reads the header at once.
   *
   * @param source the log's name for messages (a file name)
   * @throws ScanLogFormatException if it is no scan log
   */
  public ScanLogReader(Reader in, String source) throws IOException {
    this.in = Objects.requireNonNull(in, "in");
    this.source = Objects.requireNonNull(source, "source");
    this.lines = new LogLines(in, source);
    readHeader();
  }

  /**
   * Opens a log file (bytes read as ISO-8859-1, so any byte is a character and nothing fails to
   * decode).
   */
  public static ScanLogReader open(Path file) throws IOException {
    Reader r = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1);
    try {
      return new ScanLogReader(r, file.toString());
    } catch (IOException | RuntimeException e) {
      r.close();
      throw e;
    }
  }

  /** A reader of a stream of log bytes (ISO-8859-1), e.g. a log arriving over a connection. */
  public static ScanLogReader of(InputStream in, String source) throws IOException {
    return new ScanLogReader(
        new BufferedReader(new InputStreamReader(in, StandardCharsets.ISO_8859_1), 1 << 16),
        source);
  }

  /** The log's header. */
  public ScanLogHeader header() {
    return header;
  }

  /** The log's name in messages. */
  public String source() {
    return source;
  }

  /** What was read and skipped so far. */
  public ScanLogStats stats() {
    return new ScanLogStats(
        lines.lineNo(),
        scans,
        tags,
        readings,
        badReadings,
        badPoseScans,
        timeBackwards,
        truncated,
        otherLasers,
        ignored,
        endMarker);
  }

  private void readHeader() throws IOException {
    do {
      if (!lines.next()) {
        throw new ScanLogFormatException(
            source, 0, "the file is empty: a laser scan log starts with LaserOdometryLog");
      }
    } while (lines.isBlankOrComment());
    if (!lines.is("LaserOdometryLog")) {
      String first = lines.text();
      throw new ScanLogFormatException(
          source,
          lines.lineNo(),
          "a laser scan log starts with LaserOdometryLog, found '"
              + (first.length() > 40 ? first.substring(0, 40) + "..." : first)
              + "' (is this a .2d file?)");
    }
    int version = 0;
    double[] pose = {0, 0, 0, 0};
    double[] conf = {0, 0, 0};
    String name = "";
    List<String> types = List.of("robot");
    while (lines.next()) {
      if (lines.isBlankOrComment()) {
        continue;
      }
      int t = lines.tagLength();
      if (t < 0 || isBlockTag(t)) {
        held = true;
        break;
      }
      if (lines.tagIs(t, "version")) {
        version = (int) finite("version: needs a number");
      } else if (lines.tagIs(t, "sick1pose")) {
        pose[0] = finite("sick1pose: needs X Y TH as numbers");
        pose[1] = finite("sick1pose: needs X Y TH as numbers");
        pose[3] = finite("sick1pose: needs X Y TH as numbers");
      } else if (lines.tagIs(t, "scan1pose")) {
        pose[0] = finite("scan1pose: needs X Y Z TH as numbers");
        pose[1] = finite("scan1pose: needs X Y Z TH as numbers");
        pose[2] = finite("scan1pose: needs X Y Z TH as numbers");
        pose[3] = finite("scan1pose: needs X Y Z TH as numbers");
      } else if (lines.tagIs(t, "sick1conf") || lines.tagIs(t, "scan1conf")) {
        conf[0] = finite("sick1conf: needs FIRST LAST COUNT as numbers");
        conf[1] = finite("sick1conf: needs FIRST LAST COUNT as numbers");
        conf[2] = finite("sick1conf: needs FIRST LAST COUNT as numbers");
        if (conf[2] < 0 || conf[2] > 100_000) {
          throw new ScanLogFormatException(
              source, lines.lineNo(), "sick1conf: a laser has 0..100000 readings, not " + conf[2]);
        }
      } else if (lines.tagIs(t, "sick1name") || lines.tagIs(t, "scan1name")) {
        name = lines.rest();
      } else if (lines.tagIs(t, "locationTypes")) {
        types = List.of(lines.rest().split("\\s+"));
      }
    }
    header =
        new ScanLogHeader(
            version,
            new ArPose(pose[0], pose[1], pose[3]),
            pose[2],
            conf[0],
            conf[1],
            (int) conf[2],
            name,
            types);
  }

  private boolean isBlockTag(int t) {
    return lines.tagIs(t, "logTime")
        || lines.tagIs(t, "time")
        || lines.tagIs(t, "scanId")
        || lines.tagIs(t, "scan1Id")
        || lines.tagIs(t, "velocities")
        || lines.tagIs(t, "robot")
        || lines.tagIs(t, "scan1")
        || lines.tagIs(t, "sick1");
  }

  private double finite(String what) throws ScanLogFormatException {
    double v = lines.number(what);
    if (!Double.isFinite(v)) {
      throw new ScanLogFormatException(source, lines.lineNo(), what + ", found nan or inf");
    }
    return v;
  }

  /**
   * The next scan or tag, or null at the end of the log.
   *
   * @throws ScanLogFormatException if a line is broken (the message names it)
   */
  public ScanLogEntry next() throws IOException {
    while (!done) {
      if (!held && !lines.next()) {
        finish();
        return null;
      }
      held = false;
      if (!lines.terminated()) {
        // The last line of a file cut off while it was written: never trust its numbers.
        boolean endLine = lines.is("# End of log");
        endMarker |= endLine;
        if (!endLine && !lines.isBlankOrComment()) {
          blockOpen = true;
        }
        resetBlock();
        finish();
        return null;
      }
      if (lines.isBlankOrComment()) {
        if (lines.is("# End of log")) {
          endMarker = true;
        }
        continue;
      }
      ScanLogEntry e = line();
      if (e != null) {
        if (e.time() < lastTime - 0.0005) {
          timeBackwards++;
        }
        lastTime = e.time();
        return e;
      }
    }
    return null;
  }

  private void finish() {
    if (blockOpen) {
      truncated++; // a block without its readings: the file ended inside it
    }
    resetBlock();
    done = true;
  }

  private void resetBlock() {
    robot = null;
    global = null;
    scanId = -1;
  }

  /** Reads one body line; returns the entry it completes, if any. */
  private ScanLogEntry line() throws IOException {
    int t = lines.tagLength();
    if (t < 0) {
      ignored++;
      return null;
    }
    if (lines.tagIs(t, "logTime") || lines.tagIs(t, "time")) {
      resetBlock();
      blockHasScan = false;
      tagBlock = lines.tagIs(t, "time");
      blockOpen = true;
      time = lines.number(lines.tag(t) + ": needs seconds as a number");
      return null;
    }
    if (lines.tagIs(t, "velocities")) {
      vel = optional("velocities: needs VEL ROTVEL LATVEL as numbers");
      rotVel = optional("velocities: needs VEL ROTVEL LATVEL as numbers");
      latVel = optional("velocities: needs VEL ROTVEL LATVEL as numbers");
      return null;
    }
    if (lines.tagIs(t, "scanId") || lines.tagIs(t, "scan1Id")) {
      scanId = (int) lines.number(lines.tag(t) + ": needs the scan's number");
      return null;
    }
    if (lines.tagIs(t, "robot")) {
      robot = pose("robot: needs X Y TH as numbers");
      return null;
    }
    if (lines.tagIs(t, "robotGlobal")) {
      global = pose("robotGlobal: needs X Y TH as numbers");
      return null;
    }
    if (lines.tagIs(t, "scan1")) {
      return scan(false);
    }
    if (lines.tagIs(t, "sick1")) {
      return scan(true);
    }
    if (isOtherLaser(t)) {
      otherLasers++;
      resetBlock();
      return null;
    }
    if (isPoseOrReadingTag(t)) {
      return null; // robotRaw:, reflector1: ...: parts of a scan this reader does not need
    }
    if (robot == null || !tagBlock) {
      ignored++; // an info line, or an unknown tag inside a scan block
      return null;
    }
    ArPose p = robot;
    ArPose g = global;
    resetBlock();
    blockOpen = false;
    if (!usable(p) || (g != null && !usable(g))) {
      badPoseScans++;
      return null;
    }
    tags++;
    return new LogTag(time, p, g, lines.text().strip());
  }

  /** {@code scanN:} or {@code sickN:} with N other than 1. */
  private boolean isOtherLaser(int t) {
    String tag = lines.tag(t);
    if (t < 5 || !(tag.startsWith("scan") || tag.startsWith("sick"))) {
      return false;
    }
    for (int i = 4; i < t; i++) {
      if (!Character.isDigit(tag.charAt(i))) {
        return false;
      }
    }
    return !tag.equals("scan1") && !tag.equals("sick1");
  }

  /** Tags of a scan block this reader does not need (other pose kinds, reflectance). */
  private boolean isPoseOrReadingTag(int t) {
    String tag = lines.tag(t);
    return tag.startsWith("robot")
        || tag.startsWith("reflector")
        || tag.equals("scanId")
        || header.locationTypes().contains(tag);
  }

  private double optional(String what) throws ScanLogFormatException {
    return lines.hasMore() ? lines.number(what) : 0;
  }

  /** A pose line's values; {@link #BAD_POSE} if one is not finite or absurdly far. */
  private ArPose pose(String what) throws ScanLogFormatException {
    double x = lines.number(what);
    double y = lines.number(what);
    double th = lines.number(what);
    if (!(Math.abs(x) < MAX_POSE && Math.abs(y) < MAX_POSE && Math.abs(th) < MAX_POSE)) {
      return BAD_POSE;
    }
    return new ArPose(x, y, th);
  }

  /** Stands for a damaged pose line (compared by identity). */
  private static final ArPose BAD_POSE = new ArPose(0, 0, 0);

  @SuppressWarnings("ReferenceEquality") // BAD_POSE is a marker object
  private static boolean usable(ArPose p) {
    return p != BAD_POSE;
  }

  private LoggedScan scan(boolean ranges) throws IOException {
    if (robot == null && blockHasScan) {
      ignored++; // ARIA's optional second form of the same sweep (sick1: ranges and scan1: points)
      return null;
    }
    if (robot == null) {
      throw new ScanLogFormatException(
          source,
          lines.lineNo(),
          (ranges ? "sick1:" : "scan1:")
              + " readings without a robot: pose before them (each scan block is logTime:,"
              + " velocities:, scanId:, robot:, then the readings)");
    }
    int n = 0;
    String what =
        ranges ? "sick1: needs ranges as numbers" : "scan1: needs X Y pairs of numbers (mm)";
    while (lines.hasMore()) {
      if (n == xs.length) {
        xs = Arrays.copyOf(xs, n * 2);
        ys = Arrays.copyOf(ys, n * 2);
      }
      double x = lines.number(what);
      double y;
      if (ranges) {
        y = 0;
      } else if (lines.hasMore()) {
        y = lines.number(what);
      } else {
        throw new ScanLogFormatException(
            source,
            lines.lineNo(),
            "scan1: needs X Y pairs, but holds an odd number of values (" + (2 * n + 1) + ")");
      }
      if (!(Math.abs(x) <= MAX_READING) || !(Math.abs(y) <= MAX_READING)) {
        badReadings++;
        x = Double.NaN;
        y = Double.NaN;
      }
      xs[n] = x;
      ys[n] = y;
      n++;
    }
    ArPose p = robot;
    ArPose g = global;
    int id = scanId >= 0 ? scanId : scansRead;
    scansRead++;
    resetBlock();
    blockHasScan = true;
    blockOpen = false;
    if (!usable(p) || (g != null && !usable(g))) {
      badPoseScans++;
      return null;
    }
    double[] sx = Arrays.copyOf(xs, n);
    double[] sy = Arrays.copyOf(ys, n);
    if (ranges) {
      rangesToPoints(sx, sy);
    }
    scans++;
    readings += n;
    return new LoggedScan(id, time, vel, rotVel, latVel, p, g, sx, sy, true);
  }

  /** An old {@code sick1:} line's ranges as points, spread over the header's field of view. */
  private void rangesToPoints(double[] sx, double[] sy) {
    int n = sx.length;
    double first = header.firstAngle();
    double step = n < 2 ? 0 : (header.lastAngle() - first) / (n - 1);
    for (int i = 0; i < n; i++) {
      double r = sx[i];
      double a = Math.toRadians(first + i * step);
      sx[i] = Double.isNaN(r) ? Double.NaN : r * Math.cos(a);
      sy[i] = Double.isNaN(r) ? Double.NaN : r * Math.sin(a);
    }
  }

  /** Reads every remaining entry into a list (for small logs and tests). */
  public List<ScanLogEntry> readAll() throws IOException {
    List<ScanLogEntry> out = new ArrayList<>();
    for (ScanLogEntry e = next(); e != null; e = next()) {
      out.add(e);
    }
    return out;
  }

  @Override
  public void close() throws IOException {
    in.close();
  }
}
