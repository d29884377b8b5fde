package org.jaria.classroom.link;

/**
 * The student's process stopped answering on the robot link (it ended, was killed, or sent
 * something that is not a frame). The grader then decides what happened from how the process ended.
 */
public final class LinkLost extends RuntimeException {
  private static final long serialVersionUID = 1L;

  private final boolean exiting;

  /** The link broke; {@code exiting} if the student's JVM said it was shutting down. */
  public LinkLost(String message, boolean exiting, Throwable cause) {
    super(message, cause);
    this.exiting = exiting;
  }

  /** Whether the student's JVM announced it was shutting down (System.exit in its code). */
  public boolean exiting() {
    return exiting;
  }
}
