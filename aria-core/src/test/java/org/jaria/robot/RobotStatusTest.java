package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.range.ArSensorReading;
import org.junit.jupiter.api.Test;

class RobotStatusTest {

  @Test
  void theBuilderSetsEachComponentByName() {
    ArTransform turned = ArTransform.between(ArPose.ORIGIN, new ArPose(1, 2, 30));
    RobotStatus s =
        RobotStatus.builder()
            .counter(7)
            .timeNanos(11)
            .pose(new ArPose(1, 2, 3))
            .encoderPose(new ArPose(4, 5, 6))
            .rawEncoderPose(new ArPose(7, 8, 9))
            .encoderTransform(turned)
            .vel(10)
            .rotVel(11)
            .wheelVels(12, 13)
            .batteryVoltage(14)
            .realBatteryVoltage(15)
            .stallValue(16)
            .control(17)
            .flags(18)
            .compass(19)
            .anPort(20)
            .analog(21)
            .digIn(22)
            .digOut(23)
            .gripState(24)
            .chargeState(25)
            .faultFlags(26)
            .moving(true)
            .odometer(27, 28)
            .sonars(List.of(ArSensorReading.never(1, 2, 3)))
            .build();
    RobotStatus byPosition =
        new RobotStatus(
            7,
            11,
            new ArPose(1, 2, 3),
            new ArPose(4, 5, 6),
            new ArPose(7, 8, 9),
            turned,
            10,
            11,
            12,
            13,
            14,
            15,
            16,
            17,
            18,
            19,
            20,
            21,
            22,
            23,
            24,
            25,
            26,
            true,
            27,
            28,
            List.of(ArSensorReading.never(1, 2, 3)));
    assertEquals(byPosition, s);
    assertEquals(s, s.toBuilder().build());
  }

  @Test
  void aRelocalizedCopyChangesOnlyPoseTransformAndSonar() {
    RobotStatus s = RobotStatus.builder().counter(3).vel(200).pose(new ArPose(1, 1, 0)).build();
    ArTransform t = ArTransform.between(new ArPose(1, 1, 0), new ArPose(5, 5, 90));
    RobotStatus moved = s.relocalized(new ArPose(5, 5, 90), t, List.of());
    assertNotEquals(s.pose(), moved.pose());
    assertEquals(new ArPose(5, 5, 90), moved.pose());
    assertSame(t, moved.encoderTransform());
    assertEquals(200, moved.vel());
    assertEquals(3, moved.counter());
  }

  @Test
  void theInitialStatusKnowsNothing() {
    RobotStatus s = RobotStatus.initial(List.of());
    assertEquals(-1, s.counter());
    assertEquals(-1, s.chargeState());
    assertEquals(ArPose.ORIGIN, s.pose());
    assertSame(ArTransform.IDENTITY, s.encoderTransform());
  }
}
