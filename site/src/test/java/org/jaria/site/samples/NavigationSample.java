package org.jaria.site.samples;

import org.jaria.arnl.ArActionLost;
import org.jaria.arnl.ArActionSlowDownWhenNotCertain;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.map.ArMap;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/** Localization and path planning (the navigation guide). */
public final class NavigationSample {

  private NavigationSample() {}

  /** The two tasks, set up as the thesis's server program sets them up. */
  public record Navigation(ArSonarLocalizationTask loc, ArPathPlanningTask path) {}

  /**
   * Sets up sonar localization and path planning on {@code robot}; {@code lockstep} chooses the
   * synchronous modes a simulator in lockstep needs (a real robot uses the threaded ones).
   */
  public static Navigation setUp(ArRobot robot, ArMap map, boolean lockstep) {
    // tag::setup[]
    ArSonarDevice sonar = new ArSonarDevice();
    robot.addRangeDevice(sonar);
    ArSonarLocalizationTask loc =
        ArSonarLocalizationTask.builder(robot, map)
            .sonar(sonar)
            .mode(
                lockstep
                    ? ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS
                    : ArSonarLocalizationTask.UpdateMode.THREADED)
            .build();
    ArPathPlanningTask path =
        ArPathPlanningTask.builder(robot, map)
            .sonar(sonar)
            .mode(
                lockstep
                    ? ArPathPlanningTask.PlanMode.SYNCHRONOUS
                    : ArPathPlanningTask.PlanMode.THREADED)
            .build();
    // As in the thesis: slow down when unsure of the pose, stop when lost.
    path.getPathPlanActionGroup().addAction(new ArActionSlowDownWhenNotCertain(loc), 140);
    path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
    path.addGoalDoneCB(goal -> System.out.println("arrived at " + goal));
    path.addGoalFailedCB(goal -> System.out.println("failed: " + path.getFailureString()));
    // end::setup[]
    return new Navigation(loc, path);
  }
}
