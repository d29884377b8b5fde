import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;

/** Never drives: moves the simulated robot along the walls, 500 mm at a time, with SIM_SET_POSE. */
public class WallFollower extends ArAction {
  private int fired;

  public WallFollower() {
    super("teleporter");
  }

  @Override
  public ArActionDesired fire(ArActionDesired current) {
    fired++;
    if (fired % 10 == 0) {
      int step = fired / 10;
      if (step <= 12) {
        teleport(500 * step, 600, 0);
      } else if (step == 13) {
        teleport(7400, 2800, 90);
      }
    }
    return null;
  }

  private void teleport(int x, int y, int th) {
    ArRobotPacket p = new ArRobotPacket(ArCommands.SIM_SET_POSE.getNumber());
    p.uByteToBuf(0).byte4ToBuf(x).byte4ToBuf(y).byte4ToBuf(th);
    getRobot().sendPacket(p.finalizePacket());
  }
}
