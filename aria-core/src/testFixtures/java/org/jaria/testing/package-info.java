/**
 * Stand-ins for a robot that tests, benchmarks and teaching material use when no simulator is
 * wanted: {@link org.jaria.testing.FakeRobot} answers the ARCOS handshake and records what a client
 * sends, without any physics.
 *
 * <p>Published in the test kit {@code org.jaria:jaria-testing} (with the simulator's JUnit
 * extension), not in aria-core's jar: a robot program does not carry test support. Its source sits
 * in aria-core's {@code src/testFixtures/java}, because aria-core's own tests drive it too;
 * aria-core compiles it with its tests (other modules' tests get it from aria-core's test jar) and
 * jaria-testing compiles the same file into its jar.
 */
package org.jaria.testing;
