package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogHeader;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Driving round the same ring corridor again and again: the map's memory stops growing once the
 * ring is mapped (poses that repeat older ones let their points go), so a log of any length builds
 * in bounded memory. Scans are generated (ray cast against the ring's walls, odometry with a seeded
 * error), not read from a file.
 */
@Tag("slow")
class BoundedMemoryTest {

  /** The ring: outer walls 12 x 9 m, a central block 8 x 5 m; corridors 2 m wide. */
  private static final double[][] WALLS = {
    {0, 0, 12000, 0},
    {12000, 0, 12000, 9000},
    {12000, 9000, 0, 9000},
    {0, 9000, 0, 0},
    {2000, 2000, 10000, 2000},
    {10000, 2000, 10000, 7000},
    {10000, 7000, 2000, 7000},
    {2000, 7000, 2000, 2000},
    {5000, 0, 5000, 600},
    {7000, 9000, 7000, 8300}
  };

  /** The lap's corners, in the middle of the corridors. */
  private static final ArPose[] LAP = {
    new ArPose(1000, 1000), new ArPose(11000, 1000), new ArPose(11000, 8000), new ArPose(1000, 8000)
  };

  @Test
  @Timeout(value = 10, unit = TimeUnit.MINUTES) // several thousand scans on a busy machine
  void lapsAfterTheFirstDoNotGrowTheMap() {
    ScanLogHeader h = ScanLogHeader.of(ArPose.ORIGIN, -90, 90, 181, "synthetic");
    MapBuilder b = new MapBuilder(h, MapBuilderParams.DEFAULTS);
    SplittableRandom rng = new SplittableRandom(7);
    double ox = 1000;
    double oy = 1000;
    double oth = 0;
    ArPose truth = new ArPose(1000, 1000, 0);
    int id = 0;
    long afterTwo = 0;
    int laps = 6;
    for (int lap = 0; lap < laps; lap++) {
      for (int c = 0; c < 4; c++) {
        ArPose to = LAP[(c + 1) % 4];
        double heading = Math.toDegrees(Math.atan2(to.y() - truth.y(), to.x() - truth.x()));
        // turn on the spot in 25 degree steps, then drive in 300 mm steps
        double turn = org.jaria.geom.ArMath.subAngle(heading, truth.th());
        while (Math.abs(turn) > 1e-6) {
          double step = Math.copySign(Math.min(25, Math.abs(turn)), turn);
          truth = new ArPose(truth.x(), truth.y(), truth.th() + step);
          oth += step * (1 + 0.01 * rng.nextGaussian());
          turn -= step;
          b.addScan(scan(id++, truth, new ArPose(ox, oy, oth), rng));
        }
        while (truth.findDistanceTo(to) > 1) {
          double d = Math.min(300, truth.findDistanceTo(to));
          double a = Math.toRadians(truth.th());
          truth = new ArPose(truth.x() + d * Math.cos(a), truth.y() + d * Math.sin(a), truth.th());
          double dd = d * (1 + 0.02 * rng.nextGaussian());
          double oa = Math.toRadians(oth);
          ox += dd * Math.cos(oa);
          oy += dd * Math.sin(oa);
          oth += 0.2 * rng.nextGaussian();
          b.addScan(scan(id++, truth, new ArPose(ox, oy, oth), rng));
        }
      }
      if (lap == 1) {
        afterTwo = b.pointBytes();
      }
    }
    long afterAll = b.pointBytes();
    assertTrue(
        afterAll < afterTwo * 1.3,
        "points held after 2 laps " + afterTwo + " bytes, after " + laps + ": " + afterAll);
    assertTrue(
        b.posesWithPoints() < b.poseCount() / 3,
        b.posesWithPoints() + " of " + b.poseCount() + " poses hold points");
  }

  /** A 181-beam sweep from the true pose, logged with the odometry pose. */
  private static LoggedScan scan(int id, ArPose truth, ArPose odo, SplittableRandom rng) {
    double[] xs = new double[181];
    double[] ys = new double[181];
    for (int k = 0; k < 181; k++) {
      double a = Math.toRadians(truth.th() - 90 + k);
      double dx = Math.cos(a);
      double dy = Math.sin(a);
      double best = Double.POSITIVE_INFINITY;
      for (double[] w : WALLS) {
        best = Math.min(best, hit(truth.x(), truth.y(), dx, dy, w));
      }
      if (best < 30000) {
        double r = best + 5 * rng.nextGaussian();
        double la = Math.toRadians(-90 + k);
        xs[k] = Math.rint(r * Math.cos(la));
        ys[k] = Math.rint(r * Math.sin(la));
      }
    }
    return new LoggedScan(id, id * 0.5, 0, 0, 0, odo, odo, xs, ys);
  }

  /** Distance along the ray to wall w, or infinity. */
  private static double hit(double x, double y, double dx, double dy, double[] w) {
    double ex = w[2] - w[0];
    double ey = w[3] - w[1];
    double den = dx * ey - dy * ex;
    if (Math.abs(den) < 1e-12) {
      return Double.POSITIVE_INFINITY;
    }
    double t = ((w[0] - x) * ey - (w[1] - y) * ex) / den;
    double u = ((w[0] - x) * dy - (w[1] - y) * dx) / den;
    return t > 0 && u >= 0 && u <= 1 ? t : Double.POSITIVE_INFINITY;
  }
}
