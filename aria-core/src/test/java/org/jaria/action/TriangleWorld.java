package org.jaria.action;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.range.LaserScan;

/** A few wall segments and a laser that ray-casts them, for triangle-target tests. */
final class TriangleWorld {

  private final List<double[]> walls = new ArrayList<>();

  /** Adds a triangle target with its vertex at (vx, vy) pointing in direction {@code facing}. */
  TriangleWorld triangle(double vx, double vy, double facing, double side, double angle) {
    double back = Math.toRadians(facing + 180);
    double half = Math.toRadians(angle / 2);
    double ax = vx + side * Math.cos(back - half);
    double ay = vy + side * Math.sin(back - half);
    double bx = vx + side * Math.cos(back + half);
    double by = vy + side * Math.sin(back + half);
    walls.add(new double[] {ax, ay, vx, vy});
    walls.add(new double[] {vx, vy, bx, by});
    return this;
  }

  /** Adds a wall from (x1, y1) to (x2, y2). */
  TriangleWorld wall(double x1, double y1, double x2, double y2) {
    walls.add(new double[] {x1, y1, x2, y2});
    return this;
  }

  /** A scan from −90° to 90° by 0.5° from {@code sensor}, 8 m range. */
  LaserScan scan(ArPose sensor) {
    int n = 361;
    double[] ranges = new double[n];
    for (int i = 0; i < n; i++) {
      double a = Math.toRadians(sensor.th() - 90 + i * 0.5);
      double dx = Math.cos(a);
      double dy = Math.sin(a);
      double best = 8000;
      for (double[] w : walls) {
        double ex = w[2] - w[0];
        double ey = w[3] - w[1];
        double den = dx * ey - dy * ex;
        if (Math.abs(den) < 1e-12) {
          continue;
        }
        double t = ((w[0] - sensor.x()) * ey - (w[1] - sensor.y()) * ex) / den;
        double u = ((w[0] - sensor.x()) * dy - (w[1] - sensor.y()) * dx) / den;
        if (t > 0 && u >= 0 && u <= 1 && t < best) {
          best = t;
        }
      }
      ranges[i] = best;
    }
    return LaserScan.evenlySpaced(sensor, -90, 0.5, ranges, 8000);
  }
}
