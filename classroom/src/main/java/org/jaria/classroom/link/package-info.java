/**
 * The robot link between the grader and a student's program in another process: the grader hosts
 * the simulator and decides the grade; the student's JVM holds only an ArRobot whose bytes and
 * virtual time come over this link, one simulator tick at a time (lockstep across the process
 * boundary).
 */
package org.jaria.classroom.link;
