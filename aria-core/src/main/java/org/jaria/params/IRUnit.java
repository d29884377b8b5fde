package org.jaria.params;

/**
 * One infrared sensor from an {@code IRUnit <n> <type> <cycles> <x> <y>} line (PeopleBot table and
 * cliff sensors, for example).
 *
 * @param number the sensor's index (0-based; bit {@code number} of the digital inputs)
 * @param type the sensor type as ARIA numbers it
 * @param cycles how many robot cycles a detection persists
 * @param x x position on the robot, mm (forward positive)
 * @param y y position on the robot, mm (left positive)
 */
public record IRUnit(int number, int type, int cycles, int x, int y) {}
