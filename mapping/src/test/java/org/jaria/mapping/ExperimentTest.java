package org.jaria.mapping;

import java.io.StringReader;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMap;
import org.jaria.sim.OdometryError;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("experiment")
class ExperimentTest {

  @Test
  void officeLap() throws Exception {
    ArMap office = ArMap.loadBundled("office");
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
    int laps = Integer.getInteger("laps", 1);
    java.util.ArrayList<ArPose> route = new java.util.ArrayList<>();
    for (int i = 0; i < laps; i++) {
      route.addAll(lap);
    }
    ArPose start = office.findHomePose().orElseThrow();
    long t0 = System.nanoTime();
    SimDrive.Result r =
        SimDrive.record(office, 11, OdometryError.random(0.02, 0.02), start, route, 500);
    System.out.printf(
        "recorded %d scans in %.1f s, mismatched %d%n",
        r.truth().size(), (System.nanoTime() - t0) / 1e9, r.mismatched());
    java.nio.file.Files.writeString(java.nio.file.Path.of("/tmp/office.2d"), r.log());
    long t1 = System.nanoTime();
    java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
    long c1 = mx.getCurrentThreadCpuTime();
    BuiltMap m;
    try (ScanLogReader reader = new ScanLogReader(new StringReader(r.log()), "office")) {
      MapBuilder b = new MapBuilder(reader.header(), MapBuilderParams.DEFAULTS);
      for (ScanLogEntry e = reader.next(); e != null; e = reader.next()) {
        b.add(e);
      }
      m = b.finish();
    }
    System.out.printf("built in %.2f s (cpu %.2f s): %s%n", (System.nanoTime() - t1) / 1e9,
        (mx.getCurrentThreadCpuTime() - c1) / 1e9, m.stats().summary());
    // trajectory error: map frame = odometry frame; truth frame related by the first pose
    Trajectory tr = m.trajectory();
    ArPose mount = new ArPose(21, 0, 0);
    ArPose t0pose = r.truth().get(0);
    ArPose o0 = Poses.compose(tr.odometry(0), mount);
    ArPose toTruth = Poses.compose(t0pose, Poses.inverse(o0));
    double sum = 0;
    double max = 0;
    double osum = 0;
    double omax = 0;
    for (int i = 0; i < tr.size(); i++) {
      ArPose truth = r.truth().get(tr.scanId(i));
      ArPose est = Poses.compose(toTruth, Poses.compose(tr.pose(i), mount));
      ArPose odo = Poses.compose(toTruth, Poses.compose(tr.odometry(i), mount));
      double e = est.findDistanceTo(truth);
      if (i < 40 || i % 20 == 0) {
        System.out.printf("%d truth %s est %s odo %s%n", i, truth, est, odo);
      }
      double eo = odo.findDistanceTo(truth);
      sum += e * e;
      max = Math.max(max, e);
      osum += eo * eo;
      omax = Math.max(omax, eo);
    }
    System.out.printf(
        "trajectory RMS %.1f max %.1f mm (odometry RMS %.0f max %.0f) over %d scans%n",
        Math.sqrt(sum / tr.size()), max, Math.sqrt(osum / tr.size()), omax, tr.size());
    List<ArLineSegment> walls = office.getLines();
    int near = 0;
    for (int i = 0; i < m.pointCount(); i++) {
      ArPose p = Poses.compose(toTruth, new ArPose(m.x(i), m.y(i)));
      double best = Double.MAX_VALUE;
      for (ArLineSegment l : walls) {
        best = Math.min(best, dist(l, p.x(), p.y()));
      }
      for (int k = 0; k < office.getPoints().size(); k++) {
        best =
            Math.min(
                best,
                Math.hypot(office.getPoints().x(k) - p.x(), office.getPoints().y(k) - p.y()) - 30);
      }
      if (best <= 50) {
        near++;
      }
    }
    System.out.printf(
        "points %d, within 50 mm %.1f %%, lines %d%n",
        m.pointCount(), 100.0 * near / m.pointCount(), m.lines().size());
    m.writeFile(java.nio.file.Path.of("/tmp/office-built.map"));
  }

  @Test
  void pair() throws Exception {
    java.util.List<org.jaria.laser.log.LoggedScan> scans = new java.util.ArrayList<>();
    org.jaria.laser.log.ScanLogHeader h;
    try (ScanLogReader reader = ScanLogReader.open(java.nio.file.Path.of("/tmp/office.2d"))) {
      h = reader.header();
      for (ScanLogEntry e = reader.next(); e != null; e = reader.next()) {
        if (e instanceof org.jaria.laser.log.LoggedScan s) {
          scans.add(s);
        }
      }
    }
    NoEchoFilter f = new NoEchoFilter();
    for (int k = 5; k < 14; k++) {
      org.jaria.laser.log.LoggedScan a = scans.get(k - 1);
      org.jaria.laser.log.LoggedScan b = scans.get(k);
      ScanPoints pa = ScanPoints.of(a, h.laserPose(), MapBuilderParams.DEFAULTS, f);
      ScanPoints pb = ScanPoints.of(b, h.laserPose(), MapBuilderParams.DEFAULTS, f);
      PointIndex idx = new PointIndex();
      for (int i = 0; i < pa.count; i++) {
        idx.add(pa.px[i], pa.py[i]);
      }
      idx.build();
      ArPose guess = Poses.between(a.robotPose(), b.robotPose());
      IcpMatcher icp = new IcpMatcher();
      icp.setPrior(60, 1);
      icp.match(idx, pa.kx, pa.ky, pa.matchCount, 100, 0, 0);
      System.out.printf("self: %.1f %.1f %.2f%n", icp.x, icp.y, icp.thDeg);

      icp.match(idx, pb.kx, pb.ky, pb.matchCount, guess.x(), guess.y(), guess.th());
      System.out.printf(
          "%d: guess %s -> %.1f %.1f %.2f inliers %.2f pairs %d rounds %d, points %d/%d%n",
          k, guess, icp.x, icp.y, icp.thDeg, icp.inlierFraction, icp.pairs, icp.rounds,
          pa.matchCount, pb.matchCount);
    }
  }

  @Test
  void turn() throws Exception {
    ArMap office = ArMap.loadBundled("office");
    java.util.List<org.jaria.laser.log.LoggedScan> scans = new java.util.ArrayList<>();
    org.jaria.laser.log.ScanLogHeader h;
    try (ScanLogReader reader = ScanLogReader.open(java.nio.file.Path.of("/tmp/office.2d"))) {
      h = reader.header();
      for (ScanLogEntry e = reader.next(); e != null; e = reader.next()) {
        if (e instanceof org.jaria.laser.log.LoggedScan s) {
          scans.add(s);
        }
      }
    }
    // truth laser poses, recorded again with the same seed
    List<ArPose> lap = List.of(new ArPose(9000, 9500), new ArPose(9000, 12000));
    SimDrive.Result r =
        SimDrive.record(office, 11, OdometryError.random(0.02, 0.02),
            office.findHomePose().orElseThrow(), lap, 500);
    ArPose mount = new ArPose(21, 0, 0);
    NoEchoFilter f = new NoEchoFilter();
    PointIndex idx = new PointIndex();
    for (int k = 0; k < 25; k++) {
      ScanPoints p = ScanPoints.of(scans.get(k), h.laserPose(), MapBuilderParams.DEFAULTS, f);
      ArPose robot = Poses.compose(r.truth().get(k), Poses.inverse(mount));
      double c = Math.cos(robot.getThRad());
      double s = Math.sin(robot.getThRad());
      for (int i = 0; i < p.count; i++) {
        idx.add(robot.x() + c * p.px[i] - s * p.py[i], robot.y() + s * p.px[i] + c * p.py[i]);
      }
    }
    idx.build();
    for (int k = 25; k < 28; k++) {
      ScanPoints p = ScanPoints.of(scans.get(k), h.laserPose(), MapBuilderParams.DEFAULTS, f);
      ArPose truth = Poses.compose(r.truth().get(k), Poses.inverse(mount));
      IcpMatcher icp = new IcpMatcher();
      icp.setPrior(30, 3.5);
      icp.match(idx, p.kx, p.ky, p.matchCount, truth.x(), truth.y(), truth.th());
      System.out.printf("scan %d truth %s -> %.1f %.1f %.2f inl %.2f pairs %d of %d%n", k, truth,
          icp.x, icp.y, icp.thDeg, icp.inlierFraction, icp.pairs, p.matchCount);
      for (double off : new double[] {-50, -20, 20, 50}) {
        icp.match(idx, p.kx, p.ky, p.matchCount, truth.x() + off, truth.y(), truth.th());
        System.out.printf("  from %+.0f: %.1f %.1f %.2f%n", off, icp.x, icp.y, icp.thDeg);
      }
      if (k == 25) {
        double c = Math.cos(truth.getThRad());
        double s = Math.sin(truth.getThRad());
        for (int i = 0; i < p.matchCount; i++) {
          double px = truth.x() - 50 + c * p.kx[i] - s * p.ky[i];
          double py = truth.y() + s * p.kx[i] + c * p.ky[i];
          int q = idx.nearest(px, py, 90);
          if (q >= 0) {
            double ex = px - idx.x(q);
            double ey = py - idx.y(q);
            double nx = idx.nx(q);
            double rr = Double.isNaN(nx) ? Math.hypot(ex, ey) : nx * ex + idx.ny(q) * ey;
            double gx = Double.isNaN(nx) ? ex : nx * rr;
            if (Math.abs(gx) > 5) {
              System.out.printf("   p %.0f %.0f q %.0f %.0f n %.2f %.2f gx %.1f%n", px, py,
                  idx.x(q), idx.y(q), nx, idx.ny(q), gx);
            }
          }
        }
      }
    }
  }

  @Test
  void recordFixture() throws Exception {
    ArMap office = ArMap.loadBundled("office");
    List<ArPose> route =
        List.of(
            new ArPose(9000, 9500),
            new ArPose(9000, 12000),
            new ArPose(9000, 9500),
            new ArPose(2500, 9500));
    SimDrive.Result r =
        SimDrive.record(office, 3, OdometryError.random(0.02, 0.02),
            office.findHomePose().orElseThrow(), route, 500);
    java.nio.file.Path dir = java.nio.file.Path.of("src/test/resources/org/jaria/mapping");
    java.nio.file.Files.writeString(dir.resolve("office-room.2d"), r.log());
    StringBuilder sb = new StringBuilder("# scanId x y th: the true pose of the laser at each scan\n");
    for (int i = 0; i < r.truth().size(); i++) {
      ArPose t = r.truth().get(i);
      sb.append(String.format(java.util.Locale.ROOT, "%d %.1f %.1f %.3f%n", i, t.x(), t.y(), t.th()));
    }
    java.nio.file.Files.writeString(dir.resolve("office-room.truth"), sb.toString());
    System.out.println("fixture " + r.truth().size() + " scans, mismatched " + r.mismatched());
  }

  @Test
  void fixture() throws Exception {
    BuiltMap m = MapBuilderTest.build(MapBuilderTest.resource("office-room.2d"));
    List<ArPose> truth = MapBuilderTest.truth("office-room.truth");
    ArPose t = MapQuality.toTruth(m, truth, MapBuilderTest.MOUNT);
    System.out.println(MapQuality.pathError(m, truth, MapBuilderTest.MOUNT) + " " + m.stats().summary());
    ArMap office = ArMap.loadBundled("office");
    int far = 0;
    for (int i = 0; i < m.pointCount(); i++) {
      ArPose p = Poses.compose(t, new ArPose(m.x(i), m.y(i)));
      double best = Double.MAX_VALUE;
      for (ArLineSegment l : office.getLines()) {
        best = Math.min(best, dist(l, p.x(), p.y()));
      }
      for (int k = 0; k < office.getPoints().size(); k++) {
        best = Math.min(best, Math.hypot(office.getPoints().x(k) - p.x(), office.getPoints().y(k) - p.y()));
      }
      if (best > 50 && far++ % 20 == 0) {
        System.out.printf("far %.0f %.0f (%.0f)%n", p.x(), p.y(), best);
      }
    }
    System.out.println("far " + far + " of " + m.pointCount());
  }

  static double dist(ArLineSegment l, double x, double y) {
    double dx = l.x2() - l.x1();
    double dy = l.y2() - l.y1();
    double len2 = dx * dx + dy * dy;
    double t = len2 == 0 ? 0 : ((x - l.x1()) * dx + (y - l.y1()) * dy) / len2;
    t = Math.max(0, Math.min(1, t));
    return Math.hypot(l.x1() + t * dx - x, l.y1() + t * dy - y);
  }
}
