package org.jaria.arnl;

import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;

/**
 * Test helper: drives through waypoints steering by the simulator's true pose, so that a test of
 * localization does not depend on localization to drive.
 */
final class TrueRoute extends ArAction {

  private final ArActionDesired d = new ArActionDesired();
  private final SimRobot sim;
  private final List<ArPose> route;
  private final double speed;
  private int next;

  TrueRoute(SimRobot sim, List<ArPose> route, double speed) {
    super("trueRoute");
    this.sim = sim;
    this.route = route;
    this.speed = speed;
  }

  boolean done() {
    return next >= route.size();
  }

  @Override
  public ArActionDesired fire(ArActionDesired current) {
    d.reset();
    while (!done() && sim.getTruePose().findDistanceTo(route.get(next)) < 60) {
      next++;
    }
    if (done()) {
      d.setVel(0);
      d.setRotVel(0);
      return d;
    }
    ArPose p = sim.getTruePose();
    ArPose g = route.get(next);
    double dist = p.findDistanceTo(g);
    double off = ArMath.subAngle(p.findAngleTo(g), p.th());
    d.setRotVel(ArMath.clamp(2 * off, -60, 60));
    d.setVel(
        Math.abs(off) > 8
            ? 0
            : Math.min(speed, Math.sqrt(2 * 250 * Math.max(0, dist - 40)))
                * Math.cos(Math.toRadians(off)));
    return d;
  }
}
