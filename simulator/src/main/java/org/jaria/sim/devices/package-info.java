/**
 * Emulators of real devices: a simulated robot's laser presented as a real SICK LMS-200 ({@link
 * org.jaria.sim.devices.Lms200Emulator}) or Hokuyo URG ({@link org.jaria.sim.devices.UrgEmulator})
 * on a serial pseudo-terminal or a TCP port, so the drivers in {@code org.jaria.laser} are tested
 * end to end exactly as on a robot, including the faults real devices have ({@link
 * org.jaria.sim.devices.DeviceFaults}: slow answers, lost bytes, a cable pulled mid-scan).
 */
package org.jaria.sim.devices;
