/**
 * Stand-ins for a robot that tests, benchmarks and teaching material use when no simulator is
 * wanted: {@link org.jaria.testing.FakeRobot} answers the ARCOS handshake and records what a client
 * sends, without any physics.
 */
package org.jaria.testing;
