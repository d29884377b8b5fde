/**
 * Sonar localization and path planning, a SonARNL analogue (thesis §5.2), with the thesis's
 * path-following application (§6.1) in {@code org.jaria.tools.examples.NavigateDemo} (module {@code
 * tools}, run by {@code jaria demo navigate}).
 *
 * <ul>
 *   <li>{@link org.jaria.arnl.ArSonarLocalizationTask}: Monte Carlo localization on an ArMap line
 *       (and point) map with the sonar ring and odometry; corrects {@code ArRobot.getPose()}.
 *       Global localization and recovery from being lost both draw particles where the current scan
 *       fits the map, rather than scattering them blindly.
 *   <li>{@link org.jaria.arnl.ArPathPlanningTask}: plans with A* on a clearance-cost grid and
 *       drives the path with a dynamic-window local planner that avoids unmapped obstacles.
 *   <li>{@link org.jaria.arnl.ArActionLost}, {@link org.jaria.arnl.ArActionSlowDownWhenNotCertain}
 *       and {@link org.jaria.arnl.ArForbiddenRangeDevice}, as in ARNL.
 *   <li>Parameters live in an {@link org.jaria.config.ArConfig} ("Localization" and "Path planning"
 *       sections; {@link org.jaria.arnl.Arnl} bundles the typical {@code arnl.p}).
 * </ul>
 *
 * <pre>{@code
 * ArSonarDevice sonar = new ArSonarDevice();
 * robot.addRangeDevice(sonar);
 * ArSonarLocalizationTask loc = new ArSonarLocalizationTask(robot, sonar, map);
 * ArPathPlanningTask path = new ArPathPlanningTask(robot, sonar, map);
 * path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
 * loc.localizeRobotAtHomeBlocking();
 * path.pathPlanToGoal("Lab");
 * }</pre>
 *
 * <p><b>What went wrong in the thesis's building (§7.1), and what these classes do about it.</b>
 *
 * <ul>
 *   <li><i>Passages under 50 cm.</i> A sonar echo only says that something is somewhere in a 30°
 *       cone, so echoes placed on the cone's axis beside a doorway close it on the robot. Here
 *       echoes of mapped walls are recognised as such (the map, not the sonar, says where walls
 *       are: an echo at the range the map predicts in its cone is a wall, and only clears the space
 *       before it), unmapped echoes go into an occupancy grid where crossing beams clear wrongly
 *       placed ones, and the local planner checks sensed obstacles against the robot's rectangle
 *       rather than a circle. A passage must still be wider than the robot plus {@code PlanPadding}
 *       on each side (about 50 cm for a P3-DX with the defaults): that is a choice, set in {@code
 *       arnl.p}, not an accident of the sensor.
 *   <li><i>Open areas without walls.</i> Where few echoes come back, an update neither passes nor
 *       fails ({@code MinEchoes}), so the robot is not declared lost for seeing nothing; odometry
 *       carries it (the particle cloud widens as the motion model says) until walls are in range
 *       again, and {@link org.jaria.arnl.ArActionSlowDownWhenNotCertain} slows it meanwhile.
 *   <li><i>Many intermediate goals.</i> Giving a goal never touches localization: the robot keeps
 *       its particle cloud from goal to goal, so a route of many short goals costs nothing in
 *       accuracy (the demo takes several goals in sequence).
 * </ul>
 */
package org.jaria.arnl;
