package org.jaria.range;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.geom.ArPose;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The robot's queries over all its range devices ({@code checkRangeDevices...}): the closest
 * reading of any device, in the current or the cumulative buffers.
 */
class RangeDeviceQueriesTest {

  /** A device whose buffers the test fills directly (global coordinates). */
  private static final class Points extends ArRangeDevice {
    Points(String name, double maxRange) {
      super(name, maxRange, 16, 16);
    }

    synchronized Points current(double x, double y) {
      currentBuffer.addReading(x, y, 0);
      return this;
    }

    synchronized Points cumulative(double x, double y) {
      cumulativeBuffer.addReading(x, y, 0);
      return this;
    }
  }

  private final LockstepRig rig = new LockstepRig();
  private final Points far = new Points("far", 5000);
  private final Points near = new Points("near", 3000);

  @BeforeEach
  void setUp() {
    assertTrue(rig.connect());
    rig.run(200);
    rig.robot.addRangeDevice(far);
    rig.robot.addRangeDevice(near);
    far.cumulative(1000, 0); // ahead, remembered only
    near.current(600, 0).cumulative(0, 800); // ahead now; to the left, remembered
  }

  @Test
  void cumulativePolarTakesTheClosestRememberedReadingOfAnyDevice() {
    assertEquals(1000, rig.robot.checkRangeDevicesCumulativePolar(-10, 10), 1e-9);
    assertEquals(800, rig.robot.checkRangeDevicesCumulativePolar(80, 100), 1e-9);
    assertEquals(600, rig.robot.checkRangeDevicesCurrentPolar(-10, 10), 1e-9, "current differs");
    assertEquals(
        3000,
        rig.robot.checkRangeDevicesCumulativePolar(170, 190),
        1e-9,
        "nothing behind: the smallest maximum range");
  }

  @Test
  void cumulativeBoxTakesTheClosestRememberedReadingOfAnyDevice() {
    assertEquals(1000, rig.robot.checkRangeDevicesCumulativeBox(0, -100, 1500, 100), 1e-9);
    assertEquals(800, rig.robot.checkRangeDevicesCumulativeBox(-100, 500, 100, 1000), 1e-9);
    assertEquals(600, rig.robot.checkRangeDevicesCurrentBox(0, -100, 1500, 100), 1e-9);
    assertEquals(3000, rig.robot.checkRangeDevicesCumulativeBox(-1500, -100, -10, 100), 1e-9);
  }

  @Test
  void queriesAreInTheRobotsFrameAndFollowItsDevices() {
    rig.robot.moveTo(new ArPose(0, 0, 90)); // the buffers move along with the robot
    assertEquals(1000, rig.robot.checkRangeDevicesCumulativePolar(-10, 10), 1e-6);
    assertEquals(1000, rig.robot.checkRangeDevicesCumulativeBox(0, -100, 1500, 100), 1e-6);
    rig.robot.remRangeDevice(far);
    assertEquals(3000, rig.robot.checkRangeDevicesCumulativePolar(-10, 10), 1e-9);
    assertEquals(800, rig.robot.checkRangeDevicesCumulativePolar(80, 100), 1e-6);
    rig.robot.remRangeDevice(near);
    assertEquals(Double.MAX_VALUE, rig.robot.checkRangeDevicesCumulativePolar(-180, 180));
  }
}
