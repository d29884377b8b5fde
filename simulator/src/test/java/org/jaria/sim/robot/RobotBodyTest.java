package org.jaria.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import java.util.random.RandomGenerator;
import org.jaria.geom.ArPose;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SonarOptions;
import org.junit.jupiter.api.Test;

/** Which bumper bit a contact point sets, following ARIA's ArBumpers geometry. */
class RobotBodyTest {

  private static RobotBody body(double thDeg) {
    RobotModel m = RobotModel.builder("test").footprint(200, 300, 400).build();
    RandomGenerator[] r = new RandomGenerator[4];
    for (int i = 0; i < 4; i++) {
      r[i] = new SplittableRandom(i);
    }
    return new RobotBody(
        0,
        "t",
        m,
        new ArPose(1000, 2000, thDeg),
        SonarOptions.DEFAULTS,
        OdometryError.NONE,
        r,
        false,
        false,
        false);
  }

  @Test
  void frontContactsSetTheHighByteLeftmostFirst() {
    RobotBody b = body(0);
    assertEquals(1 << 11, b.bumperBits(1200, 2000), "dead ahead: middle segment 2");
    assertEquals(1 << 9, b.bumperBits(1200, 2200), "front left corner: segment 0");
    assertEquals(1 << 13, b.bumperBits(1200, 1800), "front right corner: segment 4");
  }

  @Test
  void rearContactsSetTheLowByte() {
    RobotBody b = body(0);
    assertEquals(1 << 3, b.bumperBits(700, 2000), "dead astern: middle segment 2");
    assertEquals(
        1 << 1, b.bumperBits(700, 1700), "45° right of astern: segment 0, as ARIA places it");
    assertEquals(1 << 5, b.bumperBits(700, 2300), "45° left of astern: segment 4");
  }

  @Test
  void contactsAreMeasuredInTheRobotsFrame() {
    RobotBody b = body(90);
    assertEquals(1 << 11, b.bumperBits(1000, 2200), "ahead of a robot facing +y");
    assertEquals(1 << 3, b.bumperBits(1000, 1700));
  }
}
