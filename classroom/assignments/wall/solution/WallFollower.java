import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.robot.ArRobot;

/**
 * Assignment 2 (reference solution): follows the wall on the right at 600 mm with a proportional
 * controller on the side sonar, and turns left when a wall comes up ahead.
 */
public class WallFollower extends ArAction {

  private static final double WANTED_MM = 600;
  private static final double GAIN = 0.08; // degrees per second of turn per mm of error
  private static final double MAX_TURN = 12; // degrees per second

  private final ArActionDesired desired = new ArActionDesired();

  public WallFollower() {
    super("wall follower", "keeps a wall on the right at about 600 mm");
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    desired.reset();
    double right = robot.checkRangeDevicesCurrentPolar(-100, -60);
    double ahead = robot.checkRangeDevicesCurrentPolar(-20, 20);

    if (ahead < 1200) {
      // a wall ahead: slow down and turn left until it is on the right
      desired.setVel(100);
      desired.setRotVel(35);
      return desired;
    }
    double error = Math.min(right, 2000) - WANTED_MM; // > 0: too far from the wall
    double turn = Math.max(-MAX_TURN, Math.min(MAX_TURN, -GAIN * error));
    desired.setVel(300);
    desired.setRotVel(turn);
    return desired;
  }
}
