package org.jaria.mapping;

import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.laser.log.ScanLogStats;

/**
 * Builds a map from a scan log file in one call, reporting progress as it reads: what {@code jaria
 * map build} and the map editor use.
 *
 * <pre>{@code
 * BuiltMap m = LogMapping.build(Path.of("lab.2d"), MapBuilderParams.DEFAULTS, p -> {});
 * m.writeFile(Path.of("lab.map"));
 * }</pre>
 */
public final class LogMapping {

  private LogMapping() {}

  /** A built map and what the reader skipped in the log. */
  public record Result(BuiltMap map, ScanLogStats log) {}

  /**
   * Reads {@code log} and builds its map, calling {@code progress} every 50 scans and at the end
   * (on the calling thread).
   *
   * @throws org.jaria.laser.log.ScanLogFormatException if a line of the log is broken (the message
   *     names it)
   * @throws MapBuildException if the log has no laser scans or the robot never moved
   * @throws IOException if the file cannot be read
   */
  public static Result build(Path log, MapBuilderParams params, Consumer<BuildProgress> progress)
      throws IOException, MapBuildException {
    long size = Math.max(1, Files.size(log));
    try (Counting in = new Counting(Files.newInputStream(log));
        ScanLogReader r = ScanLogReader.of(in, log.toString())) {
      MapBuilder b = new MapBuilder(r.header(), params);
      long n = 0;
      for (ScanLogEntry e = r.next(); e != null; e = r.next()) {
        b.add(e);
        if (++n % 50 == 0) {
          progress.accept(b.progress(Math.min(1, (double) in.count / size)));
        }
      }
      progress.accept(b.progress(1));
      return new Result(b.finish(), r.stats());
    }
  }

  /** Counts the bytes read, for the progress fraction. */
  private static final class Counting extends FilterInputStream {
    long count;

    Counting(InputStream in) {
      super(in);
    }

    @Override
    public int read() throws IOException {
      int b = super.read();
      if (b >= 0) {
        count++;
      }
      return b;
    }

    @Override
    public int read(byte[] buf, int off, int len) throws IOException {
      int n = super.read(buf, off, len);
      if (n > 0) {
        count += n;
      }
      return n;
    }
  }
}
