/**
 * {@code jaria laser}: reads a real laser (LMS-200 or URG) and prints its scans and rates, and
 * {@code jaria laser emulate}: presents a simulated robot's laser as a real one on a serial
 * pseudo-terminal or a TCP port, to try the first without hardware.
 */
package org.jaria.tools.laser;
