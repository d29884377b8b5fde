/**
 * The robot's rate gyro (ARIA's {@code ArAnalogGyro}): client-side integration of GYROpac samples
 * fused with the wheels' odometry ({@link org.jaria.gyro.AnalogGyroFilter}), or switching on the
 * controller's own gyro.
 */
package org.jaria.gyro;
