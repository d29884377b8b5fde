import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.robot.ArRobot;

/**
 * Assignment 2 (starter): an action that follows the wall on the robot's right at about 600 mm and
 * turns left where the wall meets another one.
 *
 * <p>Grade it: {@code ./jaria grade --assignment wall FOLDER} (FOLDER holds this file).
 */
public class WallFollower extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();

  public WallFollower() {
    super("wall follower", "keeps a wall on the right at about 600 mm");
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    desired.reset();

    // Closest sonar readings, mm from the robot's centre (0 degrees is straight ahead, positive
    // angles to the left): the right-hand side, and ahead.
    double right = robot.checkRangeDevicesCurrentPolar(-100, -60);
    double ahead = robot.checkRangeDevicesCurrentPolar(-20, 20);

    desired.setVel(300);
    // TODO steer: turn towards the wall when 'right' is more than 600 mm, away when less
    //      (desired.setRotVel(degreesPerSecond), negative turns right)
    // TODO when 'ahead' gets short, slow down and turn left
    return desired;
  }
}
