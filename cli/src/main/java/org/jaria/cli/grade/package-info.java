/**
 * {@code jaria grade} and {@code jaria bench grade}: the command line's grading, over the classroom
 * module's {@code ClassGrading}. They reach {@code jaria} through {@link
 * org.jaria.tools.cli.CommandProvider} ({@link org.jaria.cli.grade.GradingCommands}).
 */
package org.jaria.cli.grade;
