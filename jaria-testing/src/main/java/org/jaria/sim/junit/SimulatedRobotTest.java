package org.jaria.sim.junit;

import java.lang.annotation.ElementType;
import java.lang.annotation.Inherited;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * Gives a JUnit 5 test a robot connected to a fresh simulated world, on virtual time. Put it on a
 * test class or method and ask for an {@link org.jaria.robot.ArRobot} (or a {@link
 * org.jaria.sim.client.SimulatedRobot}, {@link org.jaria.sim.SimWorld}, {@link
 * org.jaria.sim.SimRobot}) as a parameter:
 *
 * <pre>{@code
 * @SimulatedRobotTest(map = "office")
 * class DriveTest {
 *   @Test
 *   void drivesOneMetre(ArRobot robot, SimulatedRobot sim) {
 *     robot.enableMotors();
 *     robot.move(1000);
 *     assertTrue(sim.runUntil(robot::isMoveDone, Duration.ofSeconds(10)));
 *   }
 * }
 * }</pre>
 *
 * <p>Each test gets its own world; nothing moves unless the test advances time ({@code
 * sim.runMillis(...)}, {@code sim.runUntil(...)}), so tests are fast and repeatable.
 */
@Target({ElementType.TYPE, ElementType.METHOD})
@Retention(RetentionPolicy.RUNTIME)
@Inherited
@ExtendWith(SimulatedRobotExtension.class)
public @interface SimulatedRobotTest {

  /** A bundled map ("office", "hall") or the path of a .map file. */
  String map() default "office";

  /** The robot model (parameter file subtype), e.g. "p3dx-sh", "p3at-sh", "amigo". */
  String robot() default "p3dx-sh";

  /** Seed for every random thing in the world (sonar noise, odometry error). */
  long seed() default 1;

  /** Whether odometry drifts like a real robot's (random error, seeded). */
  boolean odometryError() default false;
}
