package org.jaria.tools.web;

import org.jaria.map.ArMap;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.sim.SimWorld;
import org.jaria.web.control.Controls;
import org.jaria.web.source.NavigationSource;
import org.jaria.web.source.RobotDriver;
import org.jaria.web.source.SimWorldSource;
import org.jaria.web.source.SimulationControl;

/**
 * The web view's source and controls for a robot that localizes and plans (the guiServer's set-up):
 * the simulator's world when there is one, with the robot's believed pose, particles and path laid
 * over it; the arrow keys and goals through a {@link RobotDriver}.
 *
 * @param source what the page shows
 * @param controls what viewers may do
 * @param driver the driver (close it when done)
 */
public record NavigationView(
    org.jaria.web.source.FrameSource source, Controls controls, RobotDriver driver) {

  /**
   * For a simulated robot.
   *
   * @param simRobotName the robot's name in the world
   * @param speedup the world's speed-up
   */
  public static NavigationView simulated(
      SimWorld world,
      String simRobotName,
      ArnlNavigation nav,
      ArMap map,
      String mapName,
      double speedup) {
    SimulationControl sim = new SimulationControl(world, speedup);
    SimWorldSource source = new SimWorldSource(world, sim, map, mapName);
    RobotDriver driver = new RobotDriver(nav.getRobot(), nav.getPathPlanningTask());
    source.addOverlay(
        simRobotName,
        new NavigationSource(
            nav.getRobot(),
            map,
            mapName,
            nav.getLocalizationTask(),
            nav.getPathPlanningTask(),
            driver));
    return new NavigationView(source, new Controls(driver, sim), driver);
  }

  /** For a real robot: what its software knows. */
  public static NavigationView real(ArnlNavigation nav, ArMap map, String mapName) {
    RobotDriver driver = new RobotDriver(nav.getRobot(), nav.getPathPlanningTask());
    NavigationSource source =
        new NavigationSource(
            nav.getRobot(),
            map,
            mapName,
            nav.getLocalizationTask(),
            nav.getPathPlanningTask(),
            driver);
    return new NavigationView(source, new Controls(driver, null), driver);
  }
}
