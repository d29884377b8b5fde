package org.jaria.arnl;

import java.util.ArrayList;
import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;

/**
 * Test fixture: drives through waypoints steering by the simulator's true pose, so that a test (or
 * a benchmark) of localization does not depend on localization to drive. Shared with the benchmarks
 * ({@code jaria bench arnl}) through this module's test jar.
 *
 * <p>Two ways of driving: {@link #TrueRoute the tests'} brakes for every waypoint and turns on the
 * spot when the next one is more than 8° off; {@link #keepingSpeed the benchmarks'} keeps its speed
 * through the waypoints, braking only for the last one or for a turn of more than 20°, which it
 * makes on the spot, so that the robot really drives at about the speed asked.
 */
public final class TrueRoute extends ArAction {

  private final ArActionDesired d = new ArActionDesired();
  private final SimRobot sim;
  private final List<ArPose> route;
  private final double speed;
  private final double turnOnTheSpot;
  // remaining[i]: the distance from waypoint i on to the next one where the robot must stop (all
  // zero when it stops at every waypoint).
  private final double[] remaining;
  private int next;

  /** Drives {@code route} at up to {@code speed} mm/s, braking for every waypoint. */
  public TrueRoute(SimRobot sim, List<ArPose> route, double speed) {
    this(sim, route, speed, 8, new double[route.size()]);
  }

  private TrueRoute(
      SimRobot sim, List<ArPose> route, double speed, double turnOnTheSpot, double[] remaining) {
    super("trueRoute");
    this.sim = sim;
    this.route = route;
    this.speed = speed;
    this.turnOnTheSpot = turnOnTheSpot;
    this.remaining = remaining;
  }

  /**
   * Drives {@code route} at about {@code speed} mm/s, keeping the speed through waypoints where it
   * turns by 20° or less, and turning on the spot at the first waypoint (the robot may start facing
   * anywhere) and wherever the route turns more.
   */
  public static TrueRoute keepingSpeed(SimRobot sim, List<ArPose> route, double speed) {
    double[] remaining = new double[route.size()];
    for (int i = route.size() - 2; i >= 1; i--) {
      double in = route.get(i - 1).findAngleTo(route.get(i));
      double out = route.get(i).findAngleTo(route.get(i + 1));
      boolean stop = Math.abs(ArMath.subAngle(out, in)) > 20;
      remaining[i] = stop ? 0 : remaining[i + 1] + route.get(i).findDistanceTo(route.get(i + 1));
    }
    return new TrueRoute(sim, route, speed, 20, remaining);
  }

  /**
   * The office tracking route, {@code laps} times: along the corridors, into three rooms' dead ends
   * and back to the start, 77 m a lap (what {@code jaria bench arnl} and the long tracking test
   * drive).
   */
  public static List<ArPose> officeLaps(int laps) {
    List<ArPose> lap =
        List.of(
            new ArPose(9000, 9500),
            new ArPose(9000, 12000),
            new ArPose(9000, 15000),
            new ArPose(9000, 12000),
            new ArPose(9000, 9500),
            new ArPose(15000, 9500),
            new ArPose(15000, 15000),
            new ArPose(15000, 9500),
            new ArPose(26000, 9500),
            new ArPose(26250, 7000),
            new ArPose(26250, 6000),
            new ArPose(26250, 9500),
            new ArPose(1500, 9500));
    List<ArPose> route = new ArrayList<>();
    for (int i = 0; i < laps; i++) {
      route.addAll(lap);
    }
    return route;
  }

  /** Whether the last waypoint has been reached. */
  public boolean done() {
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
    double off = ArMath.subAngle(p.findAngleTo(g), p.th());
    d.setRotVel(ArMath.clamp(2 * off, -60, 60));
    double toStop = p.findDistanceTo(g) + remaining[next];
    double brake = Math.sqrt(2 * 250 * Math.max(0, toStop - 40));
    d.setVel(
        Math.abs(off) > turnOnTheSpot ? 0 : Math.min(speed, brake) * Math.cos(Math.toRadians(off)));
    return d;
  }
}
