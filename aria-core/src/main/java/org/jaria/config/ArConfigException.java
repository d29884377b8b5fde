package org.jaria.config;

/**
 * A configuration file or value was rejected. The message starts with {@code source:line:} when it
 * concerns a line of a file (so an editor can jump there), then says what is wrong and how to fix
 * it. When a file is rejected none of its values are applied.
 */
public class ArConfigException extends Exception {

  private static final long serialVersionUID = 1L;

  private final String sourceName;
  private final int line;

  /**
   * An error at a line of a file.
   *
   * @param sourceName the file name (or another description of the input)
   * @param line the 1-based line, or 0 when the problem concerns the whole input
   * @param what what is wrong and what to do about it
   */
  public ArConfigException(String sourceName, int line, String what) {
    super(sourceName + ":" + line + ": " + what);
    this.sourceName = sourceName;
    this.line = line;
  }

  /** An error at a line of a file, caused by another exception. */
  public ArConfigException(String sourceName, int line, String what, Throwable cause) {
    super(sourceName + ":" + line + ": " + what, cause);
    this.sourceName = sourceName;
    this.line = line;
  }

  /** The file name (or description) of the input. */
  public String getSourceName() {
    return sourceName;
  }

  /** The 1-based line of the problem, 0 when it concerns the whole input. */
  public int getLine() {
    return line;
  }
}
