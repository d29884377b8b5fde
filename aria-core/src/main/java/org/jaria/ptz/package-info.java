/**
 * Pan-tilt units on a robot's AUX serial port or a serial port of their own: the Sony EVI-D30/D70
 * camera ({@link org.jaria.ptz.ArSonyPTZ}, VISCA binary commands) and the Directed Perception
 * PTU-46 ({@link org.jaria.ptz.ArDPPTU}, ASCII commands). The command bytes are plain functions
 * ({@link org.jaria.ptz.Visca}, {@link org.jaria.ptz.DpptuText}) tested against byte vectors.
 */
package org.jaria.ptz;
