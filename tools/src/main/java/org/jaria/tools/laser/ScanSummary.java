package org.jaria.tools.laser;

import java.util.Locale;
import org.jaria.range.LaserScan;

/**
 * One printed line about a scan: how many readings, how many echoes, the closest one and what is
 * straight ahead, and the scan rate so far. A plain function of the scan, for testing as a value.
 */
final class ScanSummary {

  private ScanSummary() {}

  /**
   * The line for scan number {@code n}.
   *
   * @param hz scans per second so far (NaN if not known yet)
   */
  static String line(long n, LaserScan s, double hz) {
    int echoes = 0;
    int closest = -1;
    int ahead = -1;
    for (int i = 0; i < s.size(); i++) {
      double r = s.getRange(i);
      boolean echo = r > 0 && r < s.getMaxRange();
      if (echo) {
        echoes++;
        if (closest < 0 || r < s.getRange(closest)) {
          closest = i;
        }
      }
      if (ahead < 0 || Math.abs(s.getAngle(i)) < Math.abs(s.getAngle(ahead))) {
        ahead = i;
      }
    }
    StringBuilder sb = new StringBuilder();
    sb.append(String.format(Locale.ROOT, "scan %d: %d readings, %d echoes", n, s.size(), echoes));
    if (closest >= 0) {
      sb.append(
          String.format(
              Locale.ROOT, ", closest %.0f mm at %.1f°", s.getRange(closest), s.getAngle(closest)));
    }
    if (ahead >= 0) {
      double r = s.getRange(ahead);
      sb.append(
          r > 0 && r < s.getMaxRange()
              ? String.format(Locale.ROOT, ", ahead %.0f mm", r)
              : ", ahead: no echo");
    }
    if (!Double.isNaN(hz)) {
      sb.append(String.format(Locale.ROOT, ", %.1f Hz", hz));
    }
    return sb.toString();
  }
}
