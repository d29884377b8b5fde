/**
 * The classroom kit: what students' programs implement ({@link org.jaria.classroom.RobotProgram},
 * {@link org.jaria.classroom.NavigationProgram}, or an {@link org.jaria.action.ArAction}), and in
 * the sub-packages the four assignments and the grader that runs them on the simulator.
 */
package org.jaria.classroom;
