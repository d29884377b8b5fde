package org.jaria.net.server;

import java.util.function.UnaryOperator;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.guiserver.GuiServer;
import org.jaria.sim.client.SimulatedRobot;

/**
 * aria-net's {@link GuiRig} with SonARNL's localization and path planning behind the server,
 * localized at home, as the thesis's guiServer runs. It sits in the rig's package so that these
 * tests read the rig as aria-net's own tests do.
 */
final class ArnlRig extends GuiRig {

  final ArnlNavigation nav;

  private ArnlRig(UnaryOperator<GuiServer.Builder> configure) throws Exception {
    super(ArnlRig::navigation, configure);
    nav = (ArnlNavigation) services;
  }

  private static AutoCloseable navigation(SimulatedRobot sim, GuiServer.Builder b) {
    ArnlNavigation nav =
        ArnlNavigation.create(sim.robot(), OFFICE, ArnlNavigation.Mode.SYNCHRONOUS, 1);
    sim.runMillis(1500);
    nav.localizeAtHome();
    b.localization(nav.localization())
        .pathPlanning(nav.pathPlanning())
        .config(nav.configRegistry())
        .mapChange(null, nav::setMap);
    return nav;
  }

  /** A guiServer with SonARNL localization and path planning, localized at home. */
  static ArnlRig arnl() throws Exception {
    return new ArnlRig(b -> b);
  }

  /** As {@link #arnl()}, configured further (a camera, say). */
  static ArnlRig arnl(UnaryOperator<GuiServer.Builder> configure) throws Exception {
    return new ArnlRig(configure);
  }
}
