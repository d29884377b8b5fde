/**
 * Devices on a simulated robot's auxiliary serial ports (AUX1..AUX3 of the microcontroller): what a
 * client writes with TTY2/TTY3/TTY4 reaches the device, and what the device answers is buffered
 * until the client fetches it with GETAUX/GETAUX2/GETAUX3 (SERAUXpac).
 */
package org.jaria.sim.serial;
