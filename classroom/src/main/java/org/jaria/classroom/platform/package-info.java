/**
 * Grades where classes are graded: Gradescope's autograder ({@code results.json}) and GitHub
 * Classroom's autograding (a result for its reporter). The grade and the feedback are the same as
 * {@code jaria grade} gives locally, byte for byte.
 */
package org.jaria.classroom.platform;
