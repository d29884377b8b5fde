import java.util.List;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.classroom.NavigationProgram;
import org.jaria.robot.ArRobot;

/** Assignment 3 (reference solution): one goal at a time, waiting for each to be reached. */
public class GoalTour implements NavigationProgram {

  @Override
  public void run(ArRobot robot, ArPathPlanningTask path, List<String> goals)
      throws InterruptedException {
    for (String goal : goals) {
      if (!path.pathPlanToGoal(goal)) {
        System.out.println("cannot go to " + goal + ": " + path.getFailureString());
        continue;
      }
      while (path.isActive()) {
        robot.getClock().sleepMillis(100);
      }
      if (path.getState() == PathPlanningState.REACHED_GOAL) {
        System.out.println("reached " + goal + " at " + robot.getPose());
      } else {
        System.out.println("did not reach " + goal + ": " + path.getFailureString());
      }
    }
  }
}
