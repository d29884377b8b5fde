package org.jaria.laser.log;

/**
 * What a {@link ScanLogReader} read and what it skipped, so a program can say so: nothing in a log
 * is dropped without being counted here.
 *
 * @param lines lines read
 * @param scans scans returned
 * @param tags tags returned
 * @param readings readings in the returned scans
 * @param badReadings readings spelled {@code nan} or {@code inf}, or farther than a kilometre (kept
 *     as NaN: no echo)
 * @param badPoseScans scans skipped because their pose was not finite or absurdly far
 * @param timeBackwards entries whose time is earlier than the entry before (kept: a map does not
 *     need the time)
 * @param truncatedScans scans cut off by the end of the file (skipped)
 * @param otherLaserScans scans of a second or third laser ({@code scan2:} ...; skipped)
 * @param ignoredLines lines with a tag this reader does not use, or text outside a block
 * @param endMarker whether the log ended with ARIA's {@code # End of log}
 */
public record ScanLogStats(
    long lines,
    long scans,
    long tags,
    long readings,
    long badReadings,
    long badPoseScans,
    long timeBackwards,
    long truncatedScans,
    long otherLaserScans,
    long ignoredLines,
    boolean endMarker) {

  /** A one-line summary of what was skipped, empty if nothing was. */
  public String skippedSummary() {
    StringBuilder sb = new StringBuilder();
    note(sb, badReadings, "damaged readings (nan, inf or beyond 1 km) taken as no echo");
    note(sb, badPoseScans, "scans with a damaged pose skipped");
    note(sb, timeBackwards, "entries whose time went backwards (kept)");
    note(sb, truncatedScans, "scan cut off by the end of the file skipped");
    note(sb, otherLaserScans, "scans of other lasers skipped");
    note(sb, ignoredLines, "lines with unknown tags ignored");
    return sb.toString();
  }

  private static void note(StringBuilder sb, long n, String what) {
    if (n > 0) {
      sb.append(sb.length() == 0 ? "" : "; ").append(n).append(' ').append(what);
    }
  }
}
