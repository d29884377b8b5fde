package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.arnl.ArBaseLocalizationTask.UpdateMode;
import org.jaria.arnl.ArPathPlanningTask.PlanMode;
import org.jaria.clock.VirtualClock;
import org.jaria.map.ArMap;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.junit.jupiter.api.Test;

/** The {@code sonar(..)} option of both task builders does what its documentation says. */
class TaskBuilderSonarTest {

  private static final ArMap OFFICE = ArMap.loadBundled("office");

  private static ArRobot robot(String name) {
    return new ArRobot(name, new VirtualClock(), true);
  }

  private static boolean useSonar(ArPathPlanningTask t) {
    return t.getConfig().findParam("UseSonar").orElseThrow().getBool();
  }

  @Test
  void pathPlanningWithoutSonarSwitchesSonarOff() {
    ArRobot robot = robot("r");
    try (ArPathPlanningTask t =
        ArPathPlanningTask.builder(robot, OFFICE).sonar(null).mode(PlanMode.SYNCHRONOUS).build()) {
      assertFalse(useSonar(t));
    }
  }

  @Test
  void pathPlanningWithTheRobotsSonarUsesIt() {
    ArRobot robot = robot("r");
    ArSonarDevice sonar = new ArSonarDevice();
    robot.addRangeDevice(sonar);
    try (ArPathPlanningTask t =
        ArPathPlanningTask.builder(robot, OFFICE).sonar(sonar).mode(PlanMode.SYNCHRONOUS).build()) {
      assertTrue(useSonar(t));
    }
  }

  @Test
  void aSonarOfAnotherRobotIsRefused() {
    ArRobot robot = robot("mine");
    ArRobot other = robot("other");
    ArSonarDevice sonar = new ArSonarDevice();
    other.addRangeDevice(sonar);
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArPathPlanningTask.builder(robot, OFFICE).sonar(sonar));
    assertTrue(e.getMessage().contains("other"), e.getMessage());
    assertThrows(
        IllegalArgumentException.class,
        () -> ArSonarLocalizationTask.builder(robot, OFFICE).sonar(sonar));
  }

  @Test
  void localizationNeedsASonar() {
    ArRobot robot = robot("r");
    NullPointerException e =
        assertThrows(
            NullPointerException.class,
            () -> ArSonarLocalizationTask.builder(robot, OFFICE).sonar(null));
    assertTrue(e.getMessage().contains("ArSonarDevice"), e.getMessage());
    ArSonarDevice sonar = new ArSonarDevice();
    robot.addRangeDevice(sonar);
    try (ArSonarLocalizationTask t =
        ArSonarLocalizationTask.builder(robot, OFFICE)
            .sonar(sonar)
            .mode(UpdateMode.SYNCHRONOUS)
            .build()) {
      assertEquals(UpdateMode.SYNCHRONOUS, t.getUpdateMode());
      assertNotNull(robot.findSensorInterpTask("sonarLocalization"));
    }
  }
}
