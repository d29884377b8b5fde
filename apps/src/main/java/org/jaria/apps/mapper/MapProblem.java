package org.jaria.apps.mapper;

/**
 * Something wrong with a map, found by {@link MapValidator} before saving.
 *
 * @param severity how bad it is
 * @param message what is wrong and what to do, for people
 * @param itemId the editor number of the object concerned, or -1
 */
public record MapProblem(Severity severity, String message, long itemId) {

  /** How bad a problem is. */
  public enum Severity {
    /** The map will not work (the home, where the robot starts, is where no robot can stand). */
    ERROR,
    /** One place will not work, or probably a mistake (a goal no robot can reach, no name). */
    WARNING
  }

  @Override
  public String toString() {
    return (severity == Severity.ERROR ? "Error: " : "Warning: ") + message;
  }
}
