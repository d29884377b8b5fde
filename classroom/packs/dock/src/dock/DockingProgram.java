package dock;

import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;

/**
 * What a student writes for the "park in the dock" assignment: a program that drives the robot to
 * the map's dock and stops there, facing it.
 */
@FunctionalInterface
public interface DockingProgram {

  /**
   * Parks the robot in the dock.
   *
   * @param robot the connected robot; robot.getPose() is in the map's coordinates
   * @param map the room's map: map.findFirstMapObjectOfType("Dock") is where to park, and its
   *     heading the way to face
   * @throws InterruptedException if the program is stopped while it waits (let it propagate)
   */
  void run(ArRobot robot, ArMap map) throws InterruptedException;
}
