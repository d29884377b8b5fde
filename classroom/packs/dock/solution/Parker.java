import dock.DockingProgram;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;

/** Parks the robot in the room's dock: around the wall, then straight in, facing the dock. */
public class Parker implements DockingProgram {

  @Override
  public void run(ArRobot robot, ArMap map) throws InterruptedException {
    ArPose dock = map.findFirstMapObjectOfType("Dock").orElseThrow().pose();
    robot.enableMotors();
    // East along the start's row to below the dock (clear of the wall in the middle), then north.
    driveTo(robot, dock.x(), robot.getPose().y());
    driveTo(robot, dock.x(), dock.y() - 400);
    // The last stretch from where the robot really is, so small turning errors do not add up.
    driveTo(robot, dock.x(), dock.y());
    robot.setHeading(dock.th());
    waitUntilTurned(robot);
  }

  /** Turns towards (x, y) and drives there in a straight line. */
  private static void driveTo(ArRobot robot, double x, double y) throws InterruptedException {
    ArPose p = robot.getPose();
    double dx = x - p.x();
    double dy = y - p.y();
    double distance = Math.hypot(dx, dy);
    if (distance < 5) {
      return;
    }
    robot.setHeading(Math.toDegrees(Math.atan2(dy, dx)));
    waitUntilTurned(robot);
    robot.move(distance);
    while (!robot.isMoveDone()) {
      robot.getClock().sleepMillis(50);
    }
  }

  private static void waitUntilTurned(ArRobot robot) throws InterruptedException {
    while (!robot.isHeadingDone()) {
      robot.getClock().sleepMillis(50);
    }
    robot.getClock().sleepMillis(300); // let it settle
  }
}
