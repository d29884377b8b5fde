import dock.DockingProgram;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;

/** Park the robot in the room's dock: stop within 50 mm of it, facing the dock's heading. */
public class Parker implements DockingProgram {

  @Override
  public void run(ArRobot robot, ArMap map) throws InterruptedException {
    robot.enableMotors();
    // TODO: find the dock (map.findFirstMapObjectOfType("Dock")), drive around the wall in the
    // middle of the room to it, and stop there facing its heading. This only drives 1 m ahead.
    robot.move(1000);
    while (!robot.isMoveDone()) {
      robot.getClock().sleepMillis(50);
    }
  }
}
