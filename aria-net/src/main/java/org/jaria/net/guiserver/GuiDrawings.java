package org.jaria.net.guiserver;

import org.jaria.net.data.ArDrawingData;
import org.jaria.net.data.Points;
import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.server.info.ArServerInfoDrawings;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/**
 * The drawings the guiServer offers, as ARIA's range devices describe theirs: a sonar's current
 * readings ({@code sonarCurrent}, blue arrows), any other range device's current and cumulative
 * readings (a laser's blue and grey dots), and the planned path ({@code pathPlannerPath}, a red
 * line; JAria's name, since ArNetworking has no drawing for it).
 */
final class GuiDrawings {

  /** The planned path: a red line two pixels wide, above the robot. */
  static final ArDrawingData PATH =
      ArDrawingData.of("polyLine", ArDrawingData.color(255, 0, 0), 2, 55);

  private GuiDrawings() {}

  static void addDrawings(ArServerInfoDrawings drawings, ArRobot robot, PathPlanningInfo planner) {
    for (ArRangeDevice d : robot.getRangeDeviceList()) {
      if (d instanceof ArSonarDevice) {
        drawings.addRangeDevice(d, ArServerInfoDrawings.SONAR_CURRENT, null);
      } else {
        drawings.addRangeDevice(
            d, ArServerInfoDrawings.LASER_CURRENT, ArServerInfoDrawings.LASER_CUMULATIVE);
      }
    }
    if (planner != null) {
      drawings.addDrawing(PATH, "pathPlannerPath", () -> pathOf(planner));
    }
  }

  private static Points pathOf(PathPlanningInfo planner) {
    Points p = planner.getPathState().path();
    return p == null ? Points.EMPTY : p;
  }
}
