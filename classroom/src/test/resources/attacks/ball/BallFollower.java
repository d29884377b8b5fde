import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;

/** Never drives: appears next to the ball with SIM_SET_POSE, then keeps up with it the same way. */
public class BallFollower extends ArAction {
  private int fired;
  private int y = 7900;

  public BallFollower(ArACTS_1_2 acts) {
    super("teleporter");
  }

  @Override
  public ArActionDesired fire(ArActionDesired current) {
    fired++;
    if (fired == 5) {
      teleport(3800, y, 0);
    } else if (fired > 5) {
      y += 10; // the ball rolls to the left at 100 mm/s
      teleport(3800, y, 0);
    }
    return null;
  }

  private void teleport(int x, int yy, int th) {
    ArRobotPacket p = new ArRobotPacket(ArCommands.SIM_SET_POSE.getNumber());
    p.uByteToBuf(0).byte4ToBuf(x).byte4ToBuf(yy).byte4ToBuf(th);
    getRobot().sendPacket(p.finalizePacket());
  }
}
