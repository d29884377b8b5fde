package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** How a student's JVM ended, named from what the grader saw: decisions as values. */
class OutcomesTest {

  @Test
  void eachEndingHasItsStatus() {
    assertEquals(Status.TIMEOUT, Outcomes.classify(true, false, 137, ""));
    assertEquals(Status.TIMEOUT, Outcomes.classify(false, false, Outcomes.CPU_LIMIT_EXIT, ""));
    assertEquals(Status.OUT_OF_MEMORY, Outcomes.classify(false, false, 3, "(none)"));
    assertEquals(
        Status.OUT_OF_MEMORY,
        Outcomes.classify(false, false, 1, "java.lang.OutOfMemoryError: Java heap space"));
    assertEquals(
        Status.TOO_MANY_THREADS,
        Outcomes.classify(
            false, false, 3, "java.lang.OutOfMemoryError: unable to create native thread: x"));
    assertEquals(Status.EXIT, Outcomes.classify(false, true, 3, ""));
    assertEquals(Status.EXIT, Outcomes.classify(false, true, 0, ""));
    assertEquals(Status.CRASH, Outcomes.classify(false, false, 134, "hs_err"));
  }
}
