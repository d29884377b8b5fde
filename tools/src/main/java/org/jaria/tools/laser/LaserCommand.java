package org.jaria.tools.laser;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.clock.Clock;
import org.jaria.connection.RobotAddress;
import org.jaria.laser.ArLMS2xx;
import org.jaria.laser.ArLaser;
import org.jaria.laser.ArUrg;
import org.jaria.laser.LmsSettings;
import org.jaria.laser.UrgSettings;
import org.jaria.range.LaserScan;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria laser}: connects to a laser and prints one line per scan (readings, echoes, the
 * closest reading, what is ahead, the scan rate), a debugging aid like {@code jaria packets}.
 */
@Command(
    name = "laser",
    description = {
      "Read a laser range finder (SICK LMS-200 or Hokuyo URG) and print its scans and rate.",
      "Examples:",
      "  jaria laser --port /dev/ttyUSB0 --type lms2xx --baud 38400",
      "  jaria laser --port /dev/ttyACM0 --type urg --scans 10",
      "  jaria laser --port localhost:9500 --type lms2xx   (a laser behind a TCP bridge)",
      "Without hardware: jaria laser emulate --type lms2xx --device /tmp/laser (see its --help)."
    },
    subcommands = {LaserEmulateCommand.class, LaserLogCommand.class})
public final class LaserCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = {"-p", "--port"},
      description = "Serial device (/dev/ttyUSB0, COM3) or HOST:PORT of a TCP bridge.")
  String port;

  @Option(
      names = {"-t", "--type"},
      defaultValue = "lms2xx",
      description = "Laser type: lms2xx (also sick) or urg (default: ${DEFAULT-VALUE}).")
  String type;

  @Option(
      names = {"-b", "--baud"},
      description =
          "Serial rate to switch the laser to (LMS: 9600/19200/38400, default 38400;"
              + " URG: default: stay at 19200).")
  Integer baud;

  @Option(
      names = {"-n", "--scans"},
      defaultValue = "0",
      description = "Stop after this many scans (0: until interrupted).")
  long scans;

  @Option(
      names = "--timeout",
      defaultValue = "3000",
      description = "A laser silent this long (ms) counts as lost (default: ${DEFAULT-VALUE}).")
  long timeoutMs;

  @Override
  public Integer call() throws InterruptedException {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    if (port == null) {
      err.println("give the laser's port with --port (e.g. /dev/ttyUSB0 or localhost:9500)");
      return 2;
    }
    ArLaser laser;
    try {
      laser = create();
    } catch (IllegalArgumentException e) {
      err.println(e.getMessage());
      return 2;
    }
    try (laser) {
      out.println(
          "connecting to "
              + laser.getName()
              + " on "
              + laser.getDeviceConnection().getPortName()
              + " ...");
      out.flush();
      if (!laser.blockingConnect()) {
        err.println("could not connect: " + laser.getConnectFailure());
        return 1;
      }
      out.println("connected");
      if (laser instanceof ArUrg urg) {
        out.println("  " + urg.getParams());
      }
      out.flush();
      long firstAt = 0;
      for (long n = 1; scans == 0 || n <= scans; n++) {
        if (!laser.waitForScans(n, Math.max(timeoutMs, 1000) * 2)) {
          err.println(
              "laser lost: "
                  + (laser.getConnectFailure().isEmpty()
                      ? "no scan arrived"
                      : laser.getConnectFailure()));
          return 1;
        }
        long now = System.nanoTime();
        if (n == 1) {
          firstAt = now;
        }
        double hz = n > 1 ? (n - 1) / ((now - firstAt) / 1e9) : Double.NaN;
        LaserScan s = laser.getLaserScan();
        out.println(ScanSummary.line(n, s, hz));
        out.flush();
      }
      // Only a finite --scans gets here, all of them shown; the driver goes on reading while the
      // last lines print, so it may have received more: both are said, so "--scans 3" never
      // reads as "5 scans".
      out.printf(
          Locale.ROOT,
          "%d scans shown, %d received; dropped %d damaged telegrams/answers, skipped %d bytes%n",
          scans,
          laser.getScanCount(),
          laser.getDropCounters().total(),
          laser.getDropCounters().skippedBytes());
      return 0;
    }
  }

  private ArLaser create() {
    RobotAddress a = RobotAddress.parse(port);
    ArLaser laser =
        switch (type.toLowerCase(Locale.ROOT)) {
          case "lms2xx", "sick", "lms200" -> {
            LmsSettings d = LmsSettings.DEFAULT;
            yield new ArLMS2xx(
                "lms2xx_1",
                new LmsSettings(
                    d.degrees(),
                    d.increment(),
                    d.units(),
                    d.reflectorBits(),
                    baud == null ? d.baud() : baud));
          }
          case "urg", "urg2.0" -> {
            UrgSettings d = UrgSettings.DEFAULT;
            yield new ArUrg(
                "urg_1",
                new UrgSettings(
                    d.startDeg(), d.endDeg(), 1, d.startingBaud(), baud == null ? d.baud() : baud));
          }
          default ->
              throw new IllegalArgumentException("--type is lms2xx or urg, not '" + type + "'");
        };
    laser.setDeviceConnection(a.connection(Clock.system()));
    laser.setConnectionTimeoutMs(timeoutMs);
    return laser;
  }
}
