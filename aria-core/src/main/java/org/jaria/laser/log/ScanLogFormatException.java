package org.jaria.laser.log;

import java.io.IOException;

/**
 * A scan log that cannot be read as one: the message names the file, the line and what was expected
 * there, e.g. {@code lab.2d line 57: robot: needs X Y TH as numbers, found 'abc'}.
 */
public final class ScanLogFormatException extends IOException {

  private static final long serialVersionUID = 1L;

  private final long line;

  /** A problem at {@code line} (1-based; 0 if it concerns the whole file) of {@code source}. */
  public ScanLogFormatException(String source, long line, String what) {
    super(source + (line > 0 ? " line " + line : "") + ": " + what);
    this.line = line;
  }

  /** The line the problem is on (1-based), 0 if it concerns the whole file. */
  public long line() {
    return line;
  }
}
