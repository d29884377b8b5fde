package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.EncoderPacket;
import org.jaria.protocol.packets.GripState;
import org.jaria.protocol.packets.GripperPacket;
import org.jaria.protocol.packets.GyroPacket;
import org.jaria.protocol.packets.IoPacket;
import org.jaria.protocol.packets.JoystickPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.sim.robot.Gripper;
import org.jaria.sim.robot.GyroModel;
import org.jaria.sim.robot.LaserModel;
import org.junit.jupiter.api.Test;

/** Gripper, gyro, I/O, encoders, compass and laser through the protocol. */
class DevicesTest {

  private static final SimOptions OPTS = SimOptions.builder().watchdogMillis(0).build();

  @Test
  void gripperOpensAndLowersWithTravelTimes() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      // GRIPREQUEST is 37, an SRISim laser command by default: ARCOS meanings for this one.
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withLegacyLaserCommands(false));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      // stored: paddles closed (both paddle switches pressed, bits 4 and 5 clear), not open
      // (bit 0 set), lift at its top (bit 1 clear), nothing moving
      assertEquals(GripState.NOT_OPEN, r.getGripState(), "starts stored");
      c.comInt(ArCommands.GRIPPER, 8); // deploy: open paddles, lower lift
      w.step();
      int moving = r.getGripState();
      assertTrue((moving & GripState.GRIP_MOVING) != 0);
      assertTrue((moving & GripState.LIFT_MOVING) != 0);
      assertEquals(0, GripState.paddleState(moving), "paddles leave their switches at once");
      w.advanceMillis((long) Gripper.PADDLE_TRAVEL_MS - 100);
      assertTrue((r.getGripState() & GripState.GRIP_MOVING) != 0, "paddles still moving");
      w.advanceMillis(200);
      assertEquals(1, GripState.gripState(r.getGripState()), "open");
      assertTrue((r.getGripState() & GripState.LIFT_MOVING) != 0, "the lift is slower");
      assertFalse(GripState.isLiftMaxed(r.getGripState()));
      w.advanceMillis((long) (Gripper.LIFT_TRAVEL_MS - Gripper.PADDLE_TRAVEL_MS));
      int deployed = GripState.LEFT_FREE | GripState.RIGHT_FREE;
      assertEquals(deployed, r.getGripState(), "open, lift down, still");
      assertEquals(r.getGripState(), c.lastSip().getGripState(), "GRIP_STATE in the SIP");
      assertEquals(deployed, c.lastSip().getDigIn() & 0x3F, "and on DIGIN, where ARIA reads it");
      c.comInt(ArCommands.GRIPREQUEST, 1); // one packet
      GripperPacket g = GripperPacket.decode(c.awaitId(PacketIds.GRIPPER));
      assertEquals(1, g.hasGripper());
      assertEquals(deployed, g.gripState());
      c.comInt(ArCommands.GRIPPER, 2); // close
      w.advanceMillis(1000);
      c.comInt(ArCommands.GRIPPER, 3); // stop half way
      w.advanceMillis(2000);
      int half = r.getGripState();
      assertEquals(0, GripState.gripState(half), "between");
      assertEquals(0, half & GripState.GRIP_MOVING);
    }
  }

  @Test
  void gyroPacketsPrecedeEverySipAndMeasureTheTurn() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot(RobotOptions.of("p3at-sh").withGyro(true));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.GYRO, 1);
      c.comInt(ArCommands.RVEL, 60);
      w.advanceMillis(3000);
      c.clear();
      w.advanceMillis(1000);
      int gyros = 0;
      double sum = 0;
      int n = 0;
      for (int i = 0; i < c.received.size(); i++) {
        ArRobotPacket p = c.received.get(i);
        if (p.getID() == PacketIds.GYRO) {
          gyros++;
          assertTrue(
              PacketIds.isStandardSip(c.received.get(i + 1).getID()),
              "GYROpac just before the SIP");
          GyroPacket g = GyroPacket.decode(p);
          for (int k = 0; k < g.size(); k++) {
            sum += g.rate(k);
            n++;
          }
        }
      }
      assertEquals(10, gyros);
      assertEquals(40, n, "a sample every 25 ms");
      double perDps = 1 / (GyroModel.DEG_PER_COUNT * r.getModel().getGyroScaler());
      double expected = GyroModel.CENTER - 60 * perDps;
      assertEquals(expected, sum / n, 5 * GyroModel.BIAS_COUNTS, "turning ccw reads below centre");
    }
  }

  @Test
  void gyroNoiseAndBiasDriftHaveTheConfiguredStatistics() {
    GyroModel g = new GyroModel(1.626, new java.util.SplittableRandom(3));
    g.setStreaming(true);
    double sum = 0;
    double sumSq = 0;
    int n = 0;
    double bias0 = g.getBias();
    for (int tick = 0; tick < 60_000; tick++) { // 10 minutes at rest, 10 ms ticks
      g.tick(10, 0);
      for (int k = 0; k < g.pendingCount(); k++) {
        double d = g.pendingRate(k) - GyroModel.CENTER - g.getBias();
        sum += d;
        sumSq += d * d;
        n++;
      }
      g.clearPending();
    }
    assertEquals(24_000, n);
    double mean = sum / n;
    double sd = Math.sqrt(sumSq / n - mean * mean);
    assertEquals(0, mean, 0.05, "unbiased around centre + bias");
    double expectedSd = Math.sqrt(GyroModel.NOISE_COUNTS * GyroModel.NOISE_COUNTS + 1.0 / 12);
    assertEquals(expectedSd, sd, 0.05);
    double drift = Math.abs(g.getBias() - bias0);
    double walkSd = GyroModel.DRIFT_COUNTS_PER_SQRT_S * Math.sqrt(600);
    assertTrue(drift > 0, "the bias drifts");
    assertTrue(drift < 5 * walkSd, "drift " + drift + " within 5 sigma of the random walk");
  }

  @Test
  void ioAndEncoderPacketsOnRequest() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      // ADSEL is 35, an SRISim laser command by default: ARCOS meanings for this one. No gripper:
      // a gripper's switches would take DIGIN bits 0-5.
      SimRobot r =
          w.addRobot(RobotOptions.of("p3dx-sh").withLegacyLaserCommands(false).withGripper(false));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      r.setDigitalInputs(0xA5);
      r.setAnalog(2, 1000);
      c.com2Bytes(ArCommands.DIGOUT, 0x0F, 0x05); // mask 0x0F, states 0x05
      c.comInt(ArCommands.ADSEL, 2); // port 2
      c.comInt(ArCommands.IOREQUEST, 1); // one
      IoPacket io = IoPacket.decode(c.awaitId(PacketIds.IO));
      assertEquals(0xA5, io.digIn()[0]);
      assertEquals(0x05, io.digOut()[0]);
      assertEquals(0x05, r.getDigitalOutputs());
      assertEquals(1000, io.analog()[2]);
      assertEquals(9, io.analog().length);
      w.advanceMillis(200);
      assertEquals(2, c.lastSip().getAnPort());
      assertEquals(1000 >> 2, c.lastSip().getAnalog());
      assertEquals(0xA5, c.lastSip().getDigIn());
      assertEquals(0x05, c.lastSip().getDigOut());

      c.comInt(ArCommands.ENCODER, 2); // continuous
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(3000);
      List<ArRobotPacket> enc = c.packets(PacketIds.ENCODER);
      assertTrue(enc.size() >= 25);
      EncoderPacket first = EncoderPacket.decode(enc.get(0));
      EncoderPacket last = EncoderPacket.decode(enc.get(enc.size() - 1));
      assertTrue(
          last.left() > first.left() && last.right() > first.right(), "wheels turned forward");
      c.comInt(ArCommands.ENCODER, 0);
      w.step();
      int count = c.packets(PacketIds.ENCODER).size();
      w.advanceMillis(500);
      assertEquals(count, c.packets(PacketIds.ENCODER).size(), "ENCODER 0 stops them");
    }
  }

  @Test
  void joystickCompassAndBatteryTest() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(0, 0, 90)));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.JOYREQUEST, 1);
      JoystickPacket j = JoystickPacket.decode(c.awaitId(PacketIds.JOYSTICK));
      assertEquals(512, j.x());
      assertEquals(0, c.lastSip().getCompass(), "no compass until TCM2");
      c.comInt(ArCommands.TCM2, 1);
      c.comInt(ArCommands.BATTEST, 115); // 11.5 V
      w.advanceMillis(200);
      assertEquals(45, c.lastSip().getCompass(), "90° true heading, 2° per unit");
      assertEquals(115, c.lastSip().getBattery());
      c.comInt(ArCommands.TCM2, 2);
      ArRobotPacket t = c.awaitId(PacketIds.TCM2);
      t.resetRead();
      assertEquals(900, t.bufToByte2(), "TCM2pac heading, 0.1°");
      c.comInt(ArCommands.BATTEST, 0);
      c.comData(ArCommands.SAY, new byte[] {10, 60, 5, 0, 10, 64}); // three (duration, tone) pairs
      c.comInt(ArCommands.SOUNDTOG, 0); // off
      w.advanceMillis(200);
      assertEquals(130, c.lastSip().getBattery());
      assertArrayEquals(new byte[] {10, 60, 5, 0, 10, 64}, r.body().io().getLastSay());
      assertFalse(r.body().io().isSoundOn());
    }
  }

  @Test
  void laserStreamsScansIn0x60Packets() {
    List<ArLineSegment> walls = List.of(new ArLineSegment(3000, -5000, 3000, 5000));
    try (SimWorld w = SimWorld.ofLines(walls, ArPose.ORIGIN, OPTS)) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withLaser(true));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.SIM_LRF_ENABLE, 1);
      c.clear();
      w.advanceMillis(100);
      List<ArRobotPacket> scan = c.packets(PacketIds.SIM_LASER);
      assertEquals(6, scan.size(), "181 readings, 32 per packet");
      int[] ranges = new int[181];
      int got = 0;
      for (ArRobotPacket p : scan) {
        p.resetRead();
        p.bufToByte2();
        p.bufToByte2();
        p.bufToByte2();
        assertEquals(181, p.bufToUByte2());
        int first = p.bufToUByte2();
        int n = p.bufToUByte();
        for (int k = 0; k < n; k++) {
          ranges[first + k] = p.bufToUByte2();
          got++;
        }
      }
      assertEquals(181, got);
      double laserX = r.getModel().getLaserX();
      assertEquals(3000 - laserX, ranges[90], 4 * 5, "straight ahead");
      assertEquals((3000 - laserX) / Math.cos(Math.toRadians(45)), ranges[135], 30);
      SimLaserScan truth = r.getLaserScan();
      assertNotNull(truth);
      assertEquals(181, truth.size());
      assertEquals(ranges[90], truth.range(90));
    }
  }

  @Test
  void legacyLaserCommandsGiveExtendedPacketsWhenEnabled() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r =
          w.addRobot(RobotOptions.of("p3dx-sh").withLaser(true).withLegacyLaserCommands(true));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      // What old ARIA's ArSimulatedLaser sends: start, end, increment ×100, enable extended.
      c.comInt(ArCommands.GRIPPERVAL, -45);
      c.comInt(ArCommands.GRIPREQUEST, 45);
      c.comInt(ArCommands.GYROCALCW, 50);
      c.comInt(ArCommands.ADSEL, 2);
      c.clear();
      w.advanceMillis(100);
      List<ArRobotPacket> scan = c.packets(PacketIds.SIM_LASER_EXTENDED);
      assertFalse(scan.isEmpty());
      ArRobotPacket p = scan.get(0);
      p.resetRead();
      assertEquals(181, p.bufToUByte2(), "90° at 0.5°");
      assertEquals(0, p.bufToUByte2());
      assertEquals(32, p.bufToUByte());
      int range = p.bufToUByte2();
      assertEquals(LaserModel.NO_ECHO_MM, range, "nothing to see: MobileSim's no-echo value");
      assertEquals(0, p.bufToUByte(), "reflectance 0, as MobileSim for anything not a reflector");
    }
  }
}
