/**
 * Keyboard and joystick input (ARIA's {@code ArKeyHandler}, {@code ArJoyHandler} and {@code
 * ArRobotJoyHandler}): keys read from the terminal or fed by a program and bound to code, and
 * joystick state for the driving actions in {@link org.jaria.action}.
 */
package org.jaria.input;
