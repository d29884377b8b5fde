package org.jaria.classroom;

import java.util.List;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.robot.ArRobot;

/**
 * A program that sends a localized robot to goals on its map. The grader sets up what the thesis's
 * navigation server sets up — sonar, sonar localization (already localized at the map's home), path
 * planning — and hands the program the robot and the path planning task.
 */
@FunctionalInterface
public interface NavigationProgram {

  /**
   * Visits {@code goals}, names of goals on the map, in order.
   *
   * @param robot the connected, localized robot (motors enabled)
   * @param path the path planning task: {@code path.pathPlanToGoal(name)} plans and drives
   * @param goals the goal names, in the order to visit them
   * @throws InterruptedException if the program is stopped while it waits (let it propagate)
   */
  void run(ArRobot robot, ArPathPlanningTask path, List<String> goals) throws InterruptedException;
}
