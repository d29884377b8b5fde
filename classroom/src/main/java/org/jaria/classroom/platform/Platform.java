package org.jaria.classroom.platform;

/** Where a grade is reported besides the local reports. */
public enum Platform {
  /** Only the local reports. */
  LOCAL,
  /** Gradescope's autograder: results.json in the results folder. */
  GRADESCOPE,
  /** GitHub Classroom's autograding: a result for its reporter, feedback on standard output. */
  GITHUB_CLASSROOM
}
