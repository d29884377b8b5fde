package org.jaria.map;

/**
 * A map file ({@code .map}) could not be understood. The message always starts with {@code
 * source:line:} so an editor can jump to the problem, then says what is wrong and how to fix it;
 * what it quotes of the file is printable text, never raw bytes.
 */
public class MapFormatException extends Exception {

  private static final long serialVersionUID = 1L;

  private final String sourceName;
  private final int line;

  /**
   * Creates the exception.
   *
   * @param sourceName the file name (or other description) of the input
   * @param line the 1-based line number of the problem, 0 if it concerns the whole input
   * @param what what is wrong and what to do about it
   */
  public MapFormatException(String sourceName, int line, String what) {
    super(MapFormat.printable(sourceName + ":" + line + ": " + what));
    this.sourceName = sourceName;
    this.line = line;
  }

  /** The file name (or description) of the input that failed. */
  public String getSourceName() {
    return sourceName;
  }

  /** The 1-based line of the problem, 0 when it concerns the whole input. */
  public int getLine() {
    return line;
  }
}
