/**
 * Stand-ins for a robot that tests, benchmarks and teaching material use when no simulator is
 * wanted: {@link org.jaria.testing.FakeRobot} answers the ARCOS handshake and records what a client
 * sends, without any physics. It ships in the main jar, not with the test helpers, because {@code
 * jaria bench protocol} (tools) drives it outside any test.
 */
package org.jaria.testing;
