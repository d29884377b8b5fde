package org.jaria.arnl.mcl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.devices.LaserSensor;
import org.junit.jupiter.api.Test;

/** A laser scan through the shared Monte Carlo filter: it singles out the true pose. */
class LaserScansTest {

  @Test
  void aLaserScanFitsTheMapAtTheTruePoseAndNotBeside() {
    ArMap office = ArMap.loadBundled("office");
    ArPose truth = new ArPose(15000, 12500, 60);
    double[] ranges;
    ArPose mount;
    double max;
    try (SimWorld w = SimWorld.create(office, SimOptions.defaults())) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withGripper(false).withStartPose(truth));
      LaserSensor sensor = LaserSensor.of(r);
      ranges = sensor.ranges(-90, 1, 181);
      max = sensor.maxRange();
      mount =
          new ArPose(r.getModel().getLaserX(), r.getModel().getLaserY(), r.getModel().getLaserTh());
    }
    double[] angles = new double[181];
    int echoes = 0;
    for (int i = 0; i < 181; i++) {
      angles[i] = -90 + i;
      echoes += ranges[i] < max ? 1 : 0;
    }
    SonarScan scan = LaserScans.prepare(angles, ranges, mount, ArPose.ORIGIN, max, 1);
    assertEquals(echoes, scan.size(), "every echo used, no-echo beams left out");
    int evenEchoes = 0;
    for (int i = 0; i < 181; i += 2) {
      evenEchoes += ranges[i] < max ? 1 : 0;
    }
    assertEquals(
        evenEchoes,
        LaserScans.prepare(angles, ranges, mount, ArPose.ORIGIN, max, 2).size(),
        "every other beam");
    MclFilter f = new MclFilter(LikelihoodField.build(office, 50, 50, 0.1, 250), 10, 1);
    double atTruth = f.matchFraction(truth, scan, 100);
    double beside = f.matchFraction(new ArPose(truth.x() + 300, truth.y(), truth.th()), scan, 100);
    double turned = f.matchFraction(new ArPose(truth.x(), truth.y(), truth.th() + 5), scan, 100);
    assertTrue(atTruth > 0.95, "the map explains the scan at the true pose: " + atTruth);
    assertTrue(beside < atTruth - 0.2, "300 mm off: " + beside);
    assertTrue(turned < atTruth - 0.2, "5 degrees off: " + turned);
  }
}
