/**
 * Grading one assignment: the API an assignment is written against ({@link
 * org.jaria.classroom.grading.Assignment}, the type every pack's {@code META-INF/services} file
 * names, with its checks, grades and sentences), the grader that runs each student's JVM in the
 * sandbox and judges it over the robot link, and that JVM's own end of the link ({@code
 * StudentMain}, {@code StudentHarness}), which runs the assignment's student half. {@link
 * org.jaria.classroom.grading.Grading} grades in this JVM instead, for a pack's tests.
 */
package org.jaria.classroom.grading;
