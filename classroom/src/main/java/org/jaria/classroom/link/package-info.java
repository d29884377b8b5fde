/**
 * The robot link between the grader and a student's program in another process: the grader hosts
 * the simulator and decides the grade; the student's JVM holds only an ArRobot whose bytes and
 * virtual time come over this link, one simulator tick at a time (lockstep across the process
 * boundary). {@link org.jaria.classroom.link.StudentLink} is the grader's end; the student's end
 * ({@code org.jaria.classroom.grading.StudentHarness}) runs an assignment's {@link
 * org.jaria.classroom.link.StudentSide}, so it lives with the assignments' API in {@code grading}.
 * Of {@code grading} this package names only what that contract throws and takes ({@code
 * Solutions.SolutionException}, {@code Programs.Body}).
 */
package org.jaria.classroom.link;
