package org.jaria.sim.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.range.ArSimulatedLaser;
import org.jaria.range.LaserScan;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/** The client's laser device reads the simulator's laser packets. */
class SimulatedLaserTest {

  @Test
  void sweepsArriveAndMatchTheSimulatorsTruth() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(3).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArSimulatedLaser laser = new ArSimulatedLaser();
        sim.robot().addRangeDevice(laser);
        sim.runMillis(1000);
        assertTrue(laser.getSweepCount() > 3, "sweeps: " + laser.getSweepCount());
        LaserScan scan = laser.getLaserScan();
        assertNotNull(scan);
        assertEquals(181, scan.size());
        org.jaria.sim.SimLaserScan truth = r.getLaserScan();
        int compared = 0;
        for (int i = 0; i < scan.size(); i += 10) {
          if (truth.range(i) > 0 && truth.range(i) < 30000) {
            assertEquals(truth.range(i), scan.getRange(i), 60, "reading " + i);
            compared++;
          }
        }
        assertTrue(compared > 5);
        assertTrue(laser.currentReadingPolar(-10, 10) < 30000, "something ahead in the hall");
        assertTrue(sim.robot().checkRangeDevicesCurrentPolar(-90, 90) < 30000);
      }
    }
  }

  /**
   * After ARIA's own set-up sequence (as ARIA's ArSimulatedLaser sends it) the simulator streams
   * extended 0x61 packets; JAria's client reads those too.
   */
  @Test
  void extendedPacketsAfterAriasSetUpAreReadToo() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(3).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArSimulatedLaser laser = new ArSimulatedLaser();
        sim.robot().addRangeDevice(laser);
        sim.runMillis(500);
        sim.robot().comInt(36, -90);
        sim.robot().comInt(37, 90);
        sim.robot().comInt(38, 100);
        sim.robot().comInt(35, 2);
        sim.runMillis(300);
        long before = laser.getSweepCount();
        sim.runMillis(1000);
        assertTrue(laser.getSweepCount() >= before + 8, "sweeps go on: " + laser.getSweepCount());
        assertEquals(0, sim.robot().getDropCounters().total(), "nothing dropped as malformed");
        assertEquals(181, laser.getLaserScan().size());
      }
    }
  }
}
