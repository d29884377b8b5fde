package org.jaria.tools.demo;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimWorld;

/**
 * The boxes the default demo puts in the robot's way, so that there is something to avoid: three
 * crates ahead of where the robot starts, alternately left and right of its path, each reaching to
 * within a few centimetres of the robot's side. Driving straight on, the robot would brush each
 * one; its sonar sees them coming and the avoidance actions swerve it past, with room on the other
 * side (in the office corridor, 1.2 m).
 */
final class ObstaclesAhead {

  /** A crate: its centre in map coordinates (mm) and its size along and across the path. */
  record Crate(double x, double y, double along, double across) {}

  /** How far ahead of the start (mm) each crate stands, and its offset to the left of the path. */
  private static final double[][] AHEAD_AND_LEFT = {{5000, 500}, {7500, -500}, {10000, 500}};

  private static final double ALONG = 500;
  private static final double ACROSS = 500;

  private ObstaclesAhead() {}

  /** The crates for a robot starting at {@code start} (a value: nothing is placed yet). */
  static List<Crate> crates(ArPose start) {
    double th = Math.toRadians(start.th());
    double cos = Math.cos(th);
    double sin = Math.sin(th);
    List<Crate> out = new ArrayList<>();
    for (double[] al : AHEAD_AND_LEFT) {
      double x = start.x() + al[0] * cos - al[1] * sin;
      double y = start.y() + al[0] * sin + al[1] * cos;
      out.add(new Crate(x, y, ALONG, ACROSS));
    }
    return out;
  }

  /** Puts the crates for a robot starting at {@code start} into {@code world}. */
  static List<Crate> place(SimWorld world, ArPose start) {
    List<Crate> crates = crates(start);
    for (Crate c : crates) {
      world.injectBox(c.x(), c.y(), c.along(), c.across(), start.th());
    }
    return crates;
  }
}
