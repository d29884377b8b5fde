import dock.DockingProgram;
import org.jaria.map.ArMap;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.robot.ArRobot;

/** Never drives: moves the simulated robot into the dock with SIM_SET_POSE. */
public class Parker implements DockingProgram {
  public void run(ArRobot robot, ArMap map) throws InterruptedException {
    ArRobotPacket p = new ArRobotPacket(ArCommands.SIM_SET_POSE.getNumber());
    p.uByteToBuf(0).byte4ToBuf(4500).byte4ToBuf(4500).byte4ToBuf(90);
    robot.sendPacket(p.finalizePacket());
    robot.getClock().sleepMillis(2000);
  }
}
