import java.util.List;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.classroom.NavigationProgram;
import org.jaria.robot.ArRobot;

/**
 * Assignment 3 (starter): visit the named goals in order with the path planning task. The robot is
 * already localized at the map's home and its motors are on.
 *
 * <p>Grade it: {@code ./jaria grade --assignment goals FOLDER} (FOLDER holds this file).
 */
public class GoalTour implements NavigationProgram {

  @Override
  public void run(ArRobot robot, ArPathPlanningTask path, List<String> goals)
      throws InterruptedException {
    for (String goal : goals) {
      path.pathPlanToGoal(goal);
      System.out.println("going to " + goal + ": " + path.getStatusString());
      // TODO wait (on the robot's clock) until the robot has reached the goal, or failed to:
      //      path.isActive() is true while it is on its way; path.getState() says how it ended
    }
  }
}
