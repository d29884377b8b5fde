package org.jaria.mapping;

import java.io.StringWriter;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArLaserLogger;
import org.jaria.laser.log.LoggedScan;
import org.jaria.map.ArMap;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/**
 * Records a scan log on the simulator in virtual time: a P3-DX with its laser drives through
 * waypoints (steering by its true pose), an {@link ArLaserLogger} logs as sickLogger does, and the
 * robot's true pose at every logged scan is kept for comparison.
 */
final class SimDrive {

  /**
   * A recorded log and the true pose of the laser at each of its scans (the laser's, not the
   * robot's: the simulator may mount the laser elsewhere than the robot's parameter file says, as
   * MobileSim does, and only the laser's pose is observed).
   */
  record Result(String log, List<ArPose> truth, int mismatched, List<double[]> trueHits) {}

  private SimDrive() {}

  static Result record(
      ArMap map, long seed, OdometryError error, ArPose start, List<ArPose> route, double speed) {
    SimWorld world =
        SimWorld.create(map, SimOptions.builder().seed(seed).odometryError(error).build());
    SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(start));
    SimulatedRobot sim = SimulatedRobot.connect(world, r);
    try {
      ArSimulatedLaser laser = new ArSimulatedLaser();
      sim.robot().addRangeDevice(laser);
      sim.robot().enableMotors();
      sim.runMillis(1000);
      StringWriter out = new StringWriter();
      List<ArPose> truth = new ArrayList<>();
      List<double[]> hits = new ArrayList<>();
      int[] mismatched = {0};
      ArLaserLogger logger = new ArLaserLogger(sim.robot(), laser, 300, 25, out, "sim");
      logger.addEntryCB(
          e -> {
            if (e instanceof LoggedScan s) {
              org.jaria.sim.SimLaserScan t = r.getLaserScan();
              truth.add(t.origin());
              hits.add(hitsOf(t, MapBuilderParams.DEFAULTS.mapRangeMm()));
              int k = s.size() / 2;
              if (s.hasEcho(k) && Math.abs(s.range(k) - t.range(k)) > 2) {
                mismatched[0]++;
              }
            }
          });
      Driver d = new Driver(r, route, speed);
      sim.robot().addAction(d, 50);
      sim.runUntil(d::done, Duration.ofMinutes(60));
      sim.runMillis(500);
      logger.close();
      return new Result(out.toString(), truth, mismatched[0], hits);
    } finally {
      sim.close();
      world.close();
    }
  }

  /** Where the true laser's beams ended on a surface within {@code range}: x, y pairs, mm. */
  private static double[] hitsOf(org.jaria.sim.SimLaserScan t, double range) {
    double[] xy = new double[2 * t.size()];
    int n = 0;
    ArPose o = t.origin();
    for (int k = 0; k < t.size(); k++) {
      int rr = t.range(k);
      if (rr > 0 && rr <= range) {
        double a = Math.toRadians(o.th() + t.startDeg() + k * t.incrementDeg());
        xy[n++] = o.x() + rr * Math.cos(a);
        xy[n++] = o.y() + rr * Math.sin(a);
      }
    }
    return java.util.Arrays.copyOf(xy, n);
  }

  /** Steers through waypoints by the true pose; stops to turn more than 20 degrees. */
  static final class Driver extends ArAction {
    private final ArActionDesired d = new ArActionDesired();
    private final SimRobot sim;
    private final List<ArPose> route;
    private final double speed;
    private int next;

    Driver(SimRobot sim, List<ArPose> route, double speed) {
      super("waypoints");
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
      while (!done() && sim.getTruePose().findDistanceTo(route.get(next)) < 80) {
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
      d.setRotVel(ArMath.clamp(2 * off, -50, 50));
      double brake = Math.sqrt(2 * 250 * Math.max(0, p.findDistanceTo(g) - 40));
      d.setVel(Math.abs(off) > 20 ? 0 : Math.min(speed, brake) * Math.cos(Math.toRadians(off)));
      return d;
    }
  }
}
