package org.jaria.arnl.mcl;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.range.ArSensorReading;
import org.junit.jupiter.api.Test;

class MclFilterTest {

  /** A 6 m x 4 m room with a 1 m box in one corner (so that it is not symmetric). */
  static ArMap room() {
    ArMap m = new ArMap();
    m.setLines(
        List.of(
            new ArLineSegment(0, 0, 6000, 0),
            new ArLineSegment(6000, 0, 6000, 4000),
            new ArLineSegment(6000, 4000, 0, 4000),
            new ArLineSegment(0, 4000, 0, 0),
            new ArLineSegment(4500, 3000, 6000, 3000),
            new ArLineSegment(4500, 3000, 4500, 4000)));
    // The home tells free-space sampling which side of the walls is inside.
    m.addMapObject(ArMapObject.robotHome("", 1000, 1000, 0));
    return m;
  }

  /** Readings of a 16-sonar ring at {@code truth} against {@code walls}, by ray casting. */
  static List<ArSensorReading> scan(ArPose truth, List<ArLineSegment> walls, double extraShort) {
    return scan(truth, walls, extraShort, truth);
  }

  /** As above, taken when odometry said {@code odometry}. */
  static List<ArSensorReading> scan(
      ArPose truth, List<ArLineSegment> walls, double extraShort, ArPose odometry) {
    List<ArSensorReading> out = new ArrayList<>();
    double[] angles = {
      90, 50, 30, 10, -10, -30, -50, -90, -90, -130, -150, -170, 170, 150, 130, 90
    };
    for (int i = 0; i < angles.length; i++) {
      double sx = i < 8 ? 100 : -150;
      double sy = Math.sin(Math.toRadians(angles[i])) * 130;
      double th = Math.toRadians(truth.th() + angles[i]);
      double ox =
          truth.x()
              + Math.cos(Math.toRadians(truth.th())) * sx
              - Math.sin(Math.toRadians(truth.th())) * sy;
      double oy =
          truth.y()
              + Math.sin(Math.toRadians(truth.th())) * sx
              + Math.cos(Math.toRadians(truth.th())) * sy;
      // Like a real transducer: the nearest surface anywhere in the 30-degree cone.
      double r = 5000;
      for (int k = -3; k <= 3; k++) {
        for (ArLineSegment w : walls) {
          r = Math.min(r, ray(ox, oy, th + Math.toRadians(5 * k), w));
        }
      }
      if (i % 2 == 0 && extraShort > 0) {
        r = Math.min(r, extraShort);
      }
      ArSensorReading s = ArSensorReading.never(sx, sy, angles[i]);
      out.add(s.newData((int) Math.round(r), truth, odometry, 1, 0));
    }
    return out;
  }

  private static double ray(double ox, double oy, double th, ArLineSegment w) {
    double dx = Math.cos(th);
    double dy = Math.sin(th);
    double ex = w.x2() - w.x1();
    double ey = w.y2() - w.y1();
    double den = dx * ey - dy * ex;
    if (Math.abs(den) < 1e-9) {
      return Double.MAX_VALUE;
    }
    double t = ((w.x1() - ox) * ey - (w.y1() - oy) * ex) / den;
    double u = ((w.x1() - ox) * dy - (w.y1() - oy) * dx) / den;
    return t > 0 && u >= 0 && u <= 1 ? t : Double.MAX_VALUE;
  }

  private static LikelihoodField field() {
    return LikelihoodField.build(room(), 50, 100, 0.2, 250);
  }

  @Test
  void weighsTheTruePoseAboveWrongOnes() {
    ArPose truth = new ArPose(2000, 1500, 20);
    SonarScan s = SonarScan.prepare(scan(truth, room().getLines(), 0), truth, 150, 4500, 15, 7);
    MclFilter f = new MclFilter(field(), 2000, 3);
    f.initGaussian(truth, 2000, 600, 600, 20);
    f.sensorUpdate(s);
    PoseEstimate e = f.estimate();
    assertTrue(e.pose().findDistanceTo(truth) < 200, "estimate " + e);
    assertTrue(Math.abs(e.pose().th() - truth.th()) < 6, "estimate " + e);
    double atTruth = f.matchFraction(truth, s, 100);
    assertTrue(atTruth > 0.95, "score at the true pose " + atTruth);
    assertTrue(f.matchFraction(new ArPose(2600, 1500, 20), s, 100) < atTruth);
    assertTrue(f.matchFraction(new ArPose(2000, 1500, 60), s, 100) < atTruth);
  }

  @Test
  void noEchoReadingsChangeNothing() {
    ArPose truth = new ArPose(2000, 1500, 0);
    List<ArSensorReading> none = new ArrayList<>();
    for (ArSensorReading r : scan(truth, room().getLines(), 0)) {
      none.add(r.newData(5000, truth, truth, 2, 0));
    }
    SonarScan s = SonarScan.prepare(none, truth, 150, 4500, 15, 7);
    assertEquals(0, s.size());
    assertEquals(16, s.ignoredCount());
    MclFilter f = new MclFilter(field(), 500, 3);
    f.initGaussian(truth, 500, 300, 300, 10);
    double before = f.effectiveSampleSize();
    f.sensorUpdate(s);
    assertEquals(before, f.effectiveSampleSize(), 1e-9);
  }

  @Test
  void unmappedObstaclesDoNotWipeOutTheTruePose() {
    ArPose truth = new ArPose(2000, 1500, 0);
    // Half the sonars see a person 600 mm away that is not on the map.
    SonarScan s = SonarScan.prepare(scan(truth, room().getLines(), 600), truth, 150, 4500, 15, 7);
    MclFilter f = new MclFilter(field(), 2000, 5);
    f.initGaussian(truth, 2000, 400, 400, 10);
    for (int k = 0; k < 3; k++) {
      f.sensorUpdate(s);
      f.resample();
      f.jitter(20, 1);
    }
    assertTrue(f.estimate().pose().findDistanceTo(truth) < 150, f.estimate().toString());
  }

  @Test
  void motionNoiseGrowsWithDistanceNotWithTheNumberOfSteps() {
    MotionModel m = new MotionModel(0.05, 0.05, 0.0, 0, 0);
    double oneStep = spreadAfter(m, 1);
    double tenSteps = spreadAfter(m, 10);
    // Variance proportional to distance: std after 2 m = 0.05 * sqrt(2000 * 1000) mm = 70.7 mm.
    assertEquals(70.7, oneStep, 7);
    assertEquals(oneStep, tenSteps, 0.12 * oneStep);
  }

  private static double spreadAfter(MotionModel m, int steps) {
    MclFilter f = new MclFilter(field(), 5000, 11);
    f.setMotionModel(m);
    f.initGaussian(new ArPose(1000, 2000, 0), 5000, 0, 0, 0);
    for (int k = 0; k < steps; k++) {
      f.motionUpdate(
          new ArPose(2000.0 * k / steps, 0, 0), new ArPose(2000.0 * (k + 1) / steps, 0, 0));
    }
    double[] xs = new double[5000];
    double[] ys = new double[5000];
    double[] ts = new double[5000];
    double[] ws = new double[5000];
    int n = f.copySamples(xs, ys, ts, ws);
    double mean = 0;
    for (int i = 0; i < n; i++) {
      mean += xs[i] / n;
    }
    double var = 0;
    for (int i = 0; i < n; i++) {
      var += (xs[i] - mean) * (xs[i] - mean) / n;
    }
    assertEquals(3000, mean, 10);
    return Math.sqrt(var);
  }

  @Test
  void backwardsMotionMovesBackwards() {
    MclFilter f = new MclFilter(field(), 100, 1);
    f.setMotionModel(new MotionModel(0, 0, 0, 0, 0));
    f.initGaussian(new ArPose(3000, 2000, 90), 100, 0, 0, 0);
    f.motionUpdate(new ArPose(0, 0, 0), new ArPose(-500, 0, 0));
    PoseEstimate e = f.estimate();
    assertEquals(3000, e.pose().x(), 1e-6);
    assertEquals(1500, e.pose().y(), 1e-6);
    assertEquals(90, e.pose().th(), 1e-6);
  }

  @Test
  void lowVarianceResamplingKeepsProportions() {
    MclFilter f = new MclFilter(field(), 1000, 2);
    f.setMotionModel(new MotionModel(0, 0, 0, 0, 0));
    f.initGaussian(new ArPose(2000, 2000, 0), 1000, 1000, 1000, 0);
    ArPose truth = new ArPose(2000, 1500, 0);
    SonarScan s = SonarScan.prepare(scan(truth, room().getLines(), 0), truth, 150, 4500, 15, 7);
    f.sensorUpdate(s);
    double essBefore = f.effectiveSampleSize();
    f.resample();
    assertEquals(1000, f.size());
    assertEquals(1000, f.effectiveSampleSize(), 1e-6, "equal weights after resampling");
    assertTrue(essBefore < 900, "the update should have made weights unequal");
  }

  @Test
  void kldShrinksAConvergedCloudAndKeepsASpreadOne() {
    MclFilter f = new MclFilter(field(), 5000, 4);
    f.setAdjustNumSamples(true, 200, 0.05);
    f.initGaussian(new ArPose(2000, 2000, 0), 5000, 5, 5, 0.5);
    f.resample();
    assertEquals(200, f.size(), "a tight cloud needs the minimum");
    f.initUniform(5000);
    f.resample();
    assertTrue(f.size() > 2000, "a spread cloud keeps many particles: " + f.size());
  }

  @Test
  void sameSeedSameParticles() {
    ArPose truth = new ArPose(2000, 1500, 20);
    SonarScan s = SonarScan.prepare(scan(truth, room().getLines(), 0), truth, 150, 4500, 15, 7);
    double[][] a = run(s);
    double[][] b = run(s);
    assertArrayEquals(a[0], b[0]);
    assertArrayEquals(a[1], b[1]);
  }

  private static double[][] run(SonarScan s) {
    MclFilter f = new MclFilter(field(), 300, 99);
    f.initUniform(300);
    f.motionUpdate(new ArPose(0, 0, 0), new ArPose(200, 50, 5));
    f.sensorUpdate(s);
    f.resample();
    double[] xs = new double[300];
    double[] ys = new double[300];
    f.copySamples(xs, ys, new double[300], new double[300]);
    return new double[][] {xs, ys};
  }

  @Test
  void seedingFromAScanPutsParticlesWhereTheScanFits() {
    ArPose truth = new ArPose(1500, 1000, 45);
    SonarScan s = SonarScan.prepare(scan(truth, room().getLines(), 0), truth, 150, 4500, 15, 7);
    MclFilter f = new MclFilter(field(), 5000, 12);
    f.initFromScan(s, 5000, 0.2, 200, 36);
    assertEquals(5000, f.size());
    int near = nearTruth(f, truth);
    f.initUniform(5000);
    int nearUniform = nearTruth(f, truth);
    assertTrue(near > 500, "particles near the true pose after seeding: " + near);
    assertTrue(near > 20 * Math.max(1, nearUniform), near + " vs " + nearUniform + " uniform");
    // Without echoes there is nothing to go by: uniform.
    f.initFromScan(SonarScan.prepare(List.of(), truth, 150, 4500, 15, 7), 3000, 0.2, 200, 36);
    assertEquals(3000, f.size());
    assertTrue(nearTruth(f, truth) < 100);
  }

  private static int nearTruth(MclFilter f, ArPose truth) {
    double[] xs = new double[f.size()];
    double[] ys = new double[f.size()];
    double[] ts = new double[f.size()];
    int n = f.copySamples(xs, ys, ts, new double[f.size()]);
    int near = 0;
    for (int i = 0; i < n; i++) {
      if (Math.hypot(xs[i] - truth.x(), ys[i] - truth.y()) < 300
          && Math.abs(org.jaria.geom.ArMath.subAngle(ts[i], truth.th())) < 15) {
        near++;
      }
    }
    return near;
  }

  @Test
  void globalSearchFindsTheRobotInAnAsymmetricRoom() {
    ArPose truth = new ArPose(1500, 1000, 45);
    List<ArLineSegment> walls = room().getLines();
    MclFilter f = new MclFilter(field(), 20000, 8);
    f.initUniform(20000);
    ArPose odo = ArPose.ORIGIN;
    ArPose pose = truth;
    for (int k = 0; k < 12; k++) {
      SonarScan s = SonarScan.prepare(scan(pose, walls, 0, odo), odo, 150, 4500, 15, 7);
      f.sensorUpdate(s);
      f.resample();
      // Drive 200 mm along a square-ish loop, turning 30 degrees each step.
      ArPose nextOdo =
          new ArPose(
              odo.x() + 200 * Math.cos(Math.toRadians(odo.th())),
              odo.y() + 200 * Math.sin(Math.toRadians(odo.th())),
              odo.th() + 30);
      ArPose nextPose =
          new ArPose(
              pose.x() + 200 * Math.cos(Math.toRadians(pose.th())),
              pose.y() + 200 * Math.sin(Math.toRadians(pose.th())),
              pose.th() + 30);
      f.motionUpdate(odo, nextOdo);
      odo = nextOdo;
      pose = nextPose;
    }
    SonarScan s = SonarScan.prepare(scan(pose, walls, 0, odo), odo, 150, 4500, 15, 7);
    f.sensorUpdate(s);
    PoseEstimate e = f.estimate();
    assertTrue(e.pose().findDistanceTo(pose) < 250, e + " vs " + pose);
  }
}
