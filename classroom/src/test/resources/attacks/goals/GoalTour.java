import java.util.List;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.classroom.NavigationProgram;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.robot.ArRobot;

/** Never drives: moves the simulated robot onto each goal with SIM_SET_POSE. */
public class GoalTour implements NavigationProgram {
  public void run(ArRobot robot, ArPathPlanningTask path, List<String> goals)
      throws InterruptedException {
    teleport(robot, 11250, 7700, -90); // Lab Entrance
    robot.getClock().sleepMillis(2000);
    teleport(robot, 4000, 9500, 0); // Corridor West
    robot.getClock().sleepMillis(2000);
  }

  static void teleport(ArRobot robot, int x, int y, int th) {
    ArRobotPacket p = new ArRobotPacket(ArCommands.SIM_SET_POSE.getNumber());
    p.uByteToBuf(0).byte4ToBuf(x).byte4ToBuf(y).byte4ToBuf(th);
    robot.sendPacket(p.finalizePacket());
  }
}
