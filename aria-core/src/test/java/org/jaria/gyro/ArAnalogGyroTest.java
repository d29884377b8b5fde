package org.jaria.gyro;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import org.jaria.gyro.ArAnalogGyro.GyroType;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.GyroPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/** The gyro attached to a robot on the lockstep rig, fed synthetic GYROpacs. */
class ArAnalogGyroTest {

  private final LockstepRig rig = new LockstepRig();

  ArAnalogGyroTest() {
    rig.sip.setOptionalCount(9); // up to FAULT_FLAGS, so rotVel and faults come from the SIP
    if (!rig.connect()) {
      throw new IllegalStateException("rig did not connect");
    }
  }

  private boolean sent(ArCommands c, int arg) {
    return rig.fake.received(c).stream().anyMatch(x -> x.intArg() == arg);
  }

  /** A GYROpac with four samples (100 ms) of {@code reading}, then a cycle. */
  private void gyro(int reading, int packets) throws IOException {
    for (int i = 0; i < packets; i++) {
      int[] r = {reading, reading, reading, reading};
      rig.fake.send(new GyroPacket(r, new int[] {41, 41, 41, 41}).encode(new ArRobotPacket()));
      rig.run(100);
    }
  }

  @Test
  void clientSideGyroRequestsSamplesAndIntegratesThem() throws IOException {
    rig.fake.clearReceived();
    ArAnalogGyro g = new ArAnalogGyro(rig.robot, GyroType.GYRO_ANALOG_COMPUTER);
    rig.run(100);
    assertTrue(sent(ArCommands.GYRO, 1), "GYRO 1 sent");
    assertEquals(1.626, g.getFilter().getScalingFactor(), 1e-9, "GyroScaler of p3dx-sh");
    gyro(512, 12);
    assertEquals(512, g.getAverage(), 1e-9);
    assertTrue(g.haveGottenData());
    rig.sip.setPower(0, 0, 300, 0); // turning at 30 deg/s
    gyro(482, 10);
    double rate = 30 * 5.0 / 1023 * 300 / 2.5 * 1.626;
    assertEquals(40 * rate * 0.025, g.getHeading(), 1e-6);
    assertEquals(41, g.getTemperature());
    assertEquals(22, g.getPacketsReceived());
    // The gyro corrects the robot's own pose: the wheels said "no turn", the gyro said otherwise.
    assertEquals(0, rig.robot.getRawEncoderPose().th(), 1e-9);
    assertTrue(
        rig.robot.getTh() > g.getHeading() / 2,
        "pose turned with the gyro: robot " + rig.robot.getTh() + ", gyro " + g.getHeading());
    g.close();
    double th = rig.robot.getTh();
    gyro(482, 5);
    assertEquals(th, rig.robot.getTh(), 1e-9, "closed: the correction is gone");
  }

  @Test
  void aRobotThatReportsNoGyroIsLeftAlone() {
    rig.fake.clearReceived();
    ArAnalogGyro g = new ArAnalogGyro(rig.robot);
    rig.run(100);
    assertEquals(GyroType.GYRO_NONE, g.getGyroType());
    assertFalse(sent(ArCommands.GYRO, 1));
    assertEquals(2.5, g.correctedDeltaTh(0, 0, 2.5, 0), 1e-12);
  }

  @Test
  void controllerGyroIsSwitchedOnAndTrusted() {
    rig.fake.clearReceived();
    ArAnalogGyro g = new ArAnalogGyro(rig.robot, GyroType.GYRO_ANALOG_CONTROLLER);
    rig.run(100);
    assertTrue(sent(ArCommands.GYRO, 1));
    assertTrue(g.hasGyroOnlyMode());
    assertEquals(-4, g.correctedDeltaTh(0, 0, -4, 0), 1e-12, "the robot's heading is trusted");
    g.deactivate();
    rig.run(100);
    assertTrue(sent(ArCommands.GYRO, 0));
    assertTrue(g.activateGyroOnly());
    rig.run(100);
    assertTrue(sent(ArCommands.GYRO, 2));
    assertTrue(g.isGyroOnlyActive());
  }

  @Test
  void gyroOnlyModeIsRejectedForAClientSideGyro() {
    ArAnalogGyro g = new ArAnalogGyro(rig.robot, GyroType.GYRO_ANALOG_COMPUTER);
    assertFalse(g.activateGyroOnly());
    assertTrue(g.isActive());
  }

  @Test
  void aMalformedGyroPacketIsIgnored() throws IOException {
    ArAnalogGyro g = new ArAnalogGyro(rig.robot, GyroType.GYRO_ANALOG_COMPUTER);
    ArRobotPacket p = new ArRobotPacket();
    p.empty().setID(PacketIds.GYRO).uByteToBuf(5).uByte2ToBuf(512).uByteToBuf(40).finalizePacket();
    rig.fake.send(p);
    rig.run(200);
    assertEquals(0, g.getPacketsReceived());
    assertEquals(0, g.getFilter().getSampleCount());
    assertTrue(rig.robot.isConnected());
  }

  @Test
  void faultFlagsTellWhetherTheGyroWorks() {
    ArAnalogGyro g = new ArAnalogGyro(rig.robot, GyroType.GYRO_ANALOG_COMPUTER);
    assertTrue(g.isGyroWorking());
    rig.sip.setPower(0, 0, 0, 1 << 4);
    rig.run(200);
    assertFalse(g.isGyroWorking());
    rig.sip.setPower(0, 0, 0, 0);
    rig.run(200);
    assertTrue(g.isGyroWorking());
  }

  @Test
  void closeStopsTheStreamAndDetaches() throws IOException {
    ArAnalogGyro g = new ArAnalogGyro(rig.robot, GyroType.GYRO_ANALOG_COMPUTER);
    gyro(512, 1);
    FakeRobot fake = rig.fake;
    fake.clearReceived();
    g.close();
    rig.run(100);
    assertTrue(sent(ArCommands.GYRO, 0));
    gyro(512, 2);
    assertEquals(1, g.getPacketsReceived(), "no longer handled");
  }
}
