package org.jaria.range;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

class ArBumpersTest {

  @Test
  void pressedFrontBumperIsAReadingAtTheFrontThatFadesAway() {
    LockstepRig rig = new LockstepRig();
    ArBumpers bumpers = new ArBumpers();
    rig.robot.addRangeDevice(bumpers);
    assertTrue(rig.connect());
    rig.sip.setStallAndBumpers(1 << 11); // front bumper 2, the middle one of five
    rig.run(100);
    assertEquals(1, bumpers.getCurrentReadings().size());
    double d = bumpers.currentReadingPolar(-30, 30);
    assertEquals(rig.robot.getRobotLengthFront(), d, 1);
    assertEquals(5000, bumpers.currentReadingPolar(150, -150), "nothing behind");
    rig.sip.setStallAndBumpers(0);
    rig.run(16_000);
    assertEquals(0, bumpers.getCurrentReadings().size(), "gone after 15 s");
  }

  @Test
  void rearBumpersSitBehind() {
    LockstepRig rig = new LockstepRig();
    ArBumpers bumpers = new ArBumpers();
    rig.robot.addRangeDevice(bumpers);
    assertTrue(rig.connect());
    rig.sip.setStallAndBumpers(1 << 3); // rear bumper 2
    rig.run(100);
    assertTrue(bumpers.currentReadingPolar(150, -150) < 400);
    assertEquals(5000, bumpers.currentReadingPolar(-60, 60));
  }
}
