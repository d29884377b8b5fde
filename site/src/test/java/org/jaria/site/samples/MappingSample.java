package org.jaria.site.samples;

import java.io.IOException;
import java.nio.file.Path;
import org.jaria.laser.ArLaserLogger;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.MapBuildException;
import org.jaria.mapping.MapBuilder;
import org.jaria.mapping.MapBuilderParams;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.robot.ArRobot;

/** Logging laser scans from a program, and building a map from a log (the mapping guide). */
public final class MappingSample {

  private MappingSample() {}

  /** Logs while {@code drive} drives the robot; returns the scans logged. */
  public static int logWhileDriving(
      ArRobot robot, ArSimulatedLaser laser, Path file, Runnable drive) {
    // tag::log[]
    ArLaserLogger logger = new ArLaserLogger(robot, laser, 300, 25, file.toString());
    drive.run(); // your program drives; a scan is logged every 300 mm or 25 degrees
    logger.close(); // ends the log with "# End of log"
    // end::log[]
    return logger.getScanCount();
  }

  /** Builds a map from a log, scan by scan. */
  public static BuiltMap build(Path log, Path map) throws IOException, MapBuildException {
    // tag::build[]
    try (ScanLogReader reader = ScanLogReader.open(log)) {
      MapBuilder builder = new MapBuilder(reader.header(), MapBuilderParams.DEFAULTS);
      for (ScanLogEntry e = reader.next(); e != null; e = reader.next()) {
        builder.add(e); // builder.progress() and builder.snapshot() show the map growing
      }
      BuiltMap built = builder.finish();
      built.writeFile(map);
      return built;
    }
    // end::build[]
  }
}
