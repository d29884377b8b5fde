import org.jaria.classroom.RobotProgram;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.robot.ArRobot;

/** Never drives: moves the simulated robot through the square's corners with SIM_SET_POSE. */
public class Square implements RobotProgram {
  public void run(ArRobot robot) throws InterruptedException {
    int[][] corners = {{2000, 0, 90}, {2000, 2000, 180}, {0, 2000, -90}, {0, 0, 0}};
    for (int[] c : corners) {
      teleport(robot, c[0], c[1], c[2]);
      robot.getClock().sleepMillis(1000);
    }
  }

  static void teleport(ArRobot robot, int x, int y, int th) {
    ArRobotPacket p = new ArRobotPacket(ArCommands.SIM_SET_POSE.getNumber());
    p.uByteToBuf(0).byte4ToBuf(x).byte4ToBuf(y).byte4ToBuf(th);
    robot.sendPacket(p.finalizePacket());
  }
}
