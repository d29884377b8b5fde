package org.jaria.laser.log;

import java.io.IOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Objects;
import org.jaria.geom.ArPose;

/**
 * Writes a laser scan log line for line as ARIA's {@code ArLaserLogger} does, so ARIA's own tools
 * read JAria's logs: the same tags in the same order, numbers rounded as C's {@code printf} rounds
 * them ({@code %.0f} for millimetres, {@code %.2f} for degrees and velocities, ties to even), two
 * spaces after every reading pair, and {@code # End of log} when closed.
 *
 * <pre>{@code
 * try (ScanLogWriter w = new ScanLogWriter(Files.newBufferedWriter(path))) {
 *   w.writeHeader(ScanLogHeader.of(new ArPose(18, 0, 0), -90, 90, 181, "lms2xx_1"));
 *   w.writeScan(scan);
 * }
 * }</pre>
 *
 * <p>Not thread-safe: one thread writes.
 */
public final class ScanLogWriter implements AutoCloseable {

  private final Writer out;
  private final StringBuilder sb = new StringBuilder(4096);
  private boolean headerWritten;
  private boolean globalPoses = true;
  private boolean closed;

  /** A writer onto {@code out} (buffer it: the writer hands over one line at a time). */
  public ScanLogWriter(Writer out) {
    this.out = Objects.requireNonNull(out, "out");
  }

  /**
   * Writes the header: the first line, the creator comment, version, the laser's pose,
   * configuration and name (as {@code sick1...} and {@code scan1...} lines, as ARIA does) and the
   * location types.
   *
   * @throws IllegalStateException if a header was written already
   */
  public void writeHeader(ScanLogHeader h) throws IOException {
    if (headerWritten) {
      throw new IllegalStateException("a scan log has one header");
    }
    headerWritten = true;
    globalPoses = h.locationTypes().contains("robotGlobal");
    sb.setLength(0);
    sb.append("LaserOdometryLog\n#Created by ArLaserLogger\nversion: ").append(h.version());
    ArPose p = h.laserPose();
    sb.append("\nsick1pose: ");
    mm(p.x()).append(' ');
    mm(p.y()).append(' ');
    hundredths(p.th());
    sb.append("\nsick1conf: ");
    conf(h);
    sb.append("\nsick1name: ").append(h.laserName());
    sb.append("\nscan1pose: ");
    mm(p.x()).append(' ');
    mm(p.y()).append(' ');
    mm(h.laserZ()).append(' ');
    hundredths(p.th());
    sb.append("\nscan1conf: ");
    conf(h);
    sb.append("\nscan1name: ").append(h.laserName());
    sb.append("\nlocationTypes: ").append(String.join(" ", h.locationTypes())).append('\n');
    flushLine();
  }

  private void conf(ScanLogHeader h) {
    hundredths(h.firstAngle()).append(' ');
    hundredths(h.lastAngle()).append(' ').append(h.readingCount());
  }

  /**
   * Writes one scan block: {@code logTime}, {@code velocities}, {@code scanId}, the poses and the
   * {@code scan1:} readings ({@code 0 0} for a reading without echo).
   */
  public void writeScan(LoggedScan s) throws IOException {
    requireHeader();
    sb.setLength(0);
    sb.append("logTime: ");
    time(s.time());
    sb.append("\nvelocities: ");
    hundredths(s.vel()).append(' ');
    hundredths(s.rotVel()).append(' ');
    hundredths(s.latVel());
    sb.append("\nscanId: ").append(s.id()).append('\n');
    poses(s.robotPose(), s.globalPose().orElse(s.robotPose()));
    sb.append("scan1: ");
    for (int i = 0; i < s.size(); i++) {
      if (s.hasEcho(i)) {
        mm(s.x(i)).append(' ');
        mm(s.y(i)).append("  ");
      } else {
        sb.append("0 0  ");
      }
    }
    sb.append('\n');
    flushLine();
  }

  /** Writes a tag block: {@code time}, the poses and the tag's text. */
  public void writeTag(LogTag t) throws IOException {
    requireHeader();
    sb.setLength(0);
    sb.append("time: ");
    time(t.time());
    sb.append('\n');
    poses(t.robotPose(), t.global().orElse(t.robotPose()));
    sb.append(t.text()).append('\n');
    flushLine();
  }

  /** Writes a line of its own, without time or pose (ARIA's {@code addInfoToLog}). */
  public void writeInfo(String line) throws IOException {
    requireHeader();
    if (line.indexOf('\n') >= 0 || line.indexOf('\r') >= 0) {
      throw new IllegalArgumentException("an info line is one line: " + line.strip());
    }
    sb.setLength(0);
    sb.append(line).append('\n');
    flushLine();
  }

  /** Writes an entry of either kind. */
  public void write(ScanLogEntry e) throws IOException {
    if (e instanceof LoggedScan s) {
      writeScan(s);
    } else if (e instanceof LogTag t) {
      writeTag(t);
    }
  }

  /** Hands what was written to the underlying writer's destination. */
  public void flush() throws IOException {
    out.flush();
  }

  /** Writes {@code # End of log} (if a header was written) and closes the underlying writer. */
  @Override
  public void close() throws IOException {
    if (closed) {
      return;
    }
    closed = true;
    try {
      if (headerWritten) {
        out.write("# End of log\n");
      }
    } finally {
      out.close();
    }
  }

  private void requireHeader() {
    if (!headerWritten) {
      throw new IllegalStateException("write the scan log's header first");
    }
    if (closed) {
      throw new IllegalStateException("the scan log is closed");
    }
  }

  private void poses(ArPose robot, ArPose global) {
    sb.append("robot: ");
    pose(robot);
    if (globalPoses) {
      sb.append("robotGlobal: ");
      pose(global);
    }
  }

  private void pose(ArPose p) {
    mm(p.x()).append(' ');
    mm(p.y()).append(' ');
    hundredths(p.th()).append('\n');
  }

  private void flushLine() throws IOException {
    out.append(sb);
  }

  /** {@code %ld.%03ld} of whole milliseconds. */
  private void time(double seconds) {
    long ms = Math.round(seconds * 1000);
    if (ms < 0) {
      sb.append('-');
      ms = -ms;
    }
    long frac = ms % 1000;
    sb.append(ms / 1000).append('.');
    if (frac < 100) {
      sb.append('0');
    }
    if (frac < 10) {
      sb.append('0');
    }
    sb.append(frac);
  }

  /** C's {@code %.0f}: round half to even, {@code -0} for small negatives, {@code nan}. */
  private StringBuilder mm(double v) {
    if (!Double.isFinite(v)) {
      return sb.append(Double.isNaN(v) ? "nan" : v > 0 ? "inf" : "-inf");
    }
    double r = Math.rint(v);
    if (r == 0 && (v < 0 || 1 / v < 0)) {
      return sb.append("-0");
    }
    return sb.append((long) r);
  }

  /** C's {@code %.2f}: the exact binary value rounded half to even. */
  private StringBuilder hundredths(double v) {
    if (!Double.isFinite(v)) {
      return sb.append(Double.isNaN(v) ? "nan" : v > 0 ? "inf" : "-inf");
    }
    String s = new BigDecimal(v).setScale(2, RoundingMode.HALF_EVEN).toPlainString();
    if (v < 0 && !s.startsWith("-")) {
      sb.append('-');
    }
    return sb.append(s);
  }
}
