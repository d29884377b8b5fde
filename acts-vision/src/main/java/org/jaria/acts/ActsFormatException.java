package org.jaria.acts;

import java.io.IOException;

/**
 * A file (channel LUT, runtime configuration, preferences, image) could not be read because its
 * contents are damaged or not in the expected format. The message names the file and, where it
 * makes sense, the line or byte offset, says what was wrong and what to do about it.
 *
 * <p>Whatever was being loaded into is left as it was before the load started.
 */
public final class ActsFormatException extends IOException {

  private static final long serialVersionUID = 1L;

  private final String source;
  private final long position;

  /**
   * A format error.
   *
   * @param source the file name (or another description of where the bytes came from)
   * @param position the 1-based line number for text formats, the byte offset for binary ones, or
   *     -1 when no position applies
   * @param message what is wrong, and what to do
   */
  public ActsFormatException(String source, long position, String message) {
    super(source + (position >= 0 ? ":" + position : "") + ": " + message);
    this.source = source;
    this.position = position;
  }

  /** The file name or description of the damaged input. */
  public String getSource() {
    return source;
  }

  /** The line number or byte offset of the problem, or -1. */
  public long getPosition() {
    return position;
  }
}
