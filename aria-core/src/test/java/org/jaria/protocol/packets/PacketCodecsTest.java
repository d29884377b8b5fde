package org.jaria.protocol.packets;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.protocol.ArRobotPacket;
import org.junit.jupiter.api.Test;

class PacketCodecsTest {

  private final ArRobotPacket p = new ArRobotPacket();

  /** A copy of the encoded packet cut to {@code keep} payload bytes (re-checksummed). */
  private static ArRobotPacket truncated(ArRobotPacket full, int keep) {
    ArRobotPacket t = new ArRobotPacket(full.getID());
    full.resetRead();
    byte[] data = new byte[keep];
    full.bufToData(data, 0, keep);
    return t.dataToBuf(data, 0, keep).finalizePacket();
  }

  @Test
  void standardSipRoundTripsWithEveryTailLength() {
    for (int tail = 0; tail <= StandardSip.Optional.values().length; tail++) {
      StandardSip s = new StandardSip();
      s.setMoving(true).setPos(30000, 12345, -1024).setWheelVels(-300, 310).setBattery(129);
      s.setStallAndBumpers(0x0103).setControl(-45).setFlags(0x1F).setCompass(90);
      s.addSonar(0, 500).addSonar(7, 5000).addSonar(15, 123);
      s.setIo(3, 2, 200, 0xAA, 0x55).setPower(131, 2, -123, 7);
      s.setExtended(-5, 31, 88, 123456789L, 0xDEADBEEFL);
      s.setOptionalCount(tail);
      s.encode(p);
      assertTrue(p.verifyCheckSum());
      StandardSip d = new StandardSip();
      assertTrue(d.decode(p), "tail " + tail);
      assertEquals(PacketIds.SIP_MOVING, d.getId());
      assertEquals(30000, d.getXPos());
      assertEquals(12345, d.getYPos());
      assertEquals(-1024, d.getThPos());
      assertEquals(-300, d.getLeftVel());
      assertEquals(310, d.getRightVel());
      assertEquals(129, d.getBattery());
      assertEquals(0x0103, d.getStallAndBumpers());
      assertEquals(-45, d.getControl());
      assertEquals(0x1F, d.getFlags());
      assertEquals(90, d.getCompass());
      assertEquals(3, d.getSonarCount());
      assertEquals(7, d.getSonarNumber(1));
      assertEquals(5000, d.getSonarRange(1));
      assertEquals(tail, d.getOptionalCount());
      if (tail >= 5) {
        assertEquals(3, d.getGripState());
        assertEquals(0x55, d.getDigOut());
      }
      if (tail >= 9) {
        assertEquals(131, d.getBatteryX10());
        assertEquals(2, d.getChargeState());
        assertEquals(-123, d.getRotVel());
        assertEquals(7, d.getFaultFlags());
      }
      if (tail == 14) {
        assertEquals(123456789L, d.getUcTime());
        assertEquals(0xDEADBEEFL, d.getFlags3());
        assertEquals(-5, d.getLatVel());
        assertEquals(31, d.getTemperature());
      }
    }
  }

  @Test
  void positionIsReducedTo15Bits() {
    new StandardSip().setPos(0xFFFF, 0x8001, 0).encode(p);
    StandardSip d = new StandardSip();
    assertTrue(d.decode(p));
    assertEquals(0x7FFF, d.getXPos());
    assertEquals(1, d.getYPos());
  }

  @Test
  void truncatedSipIsRejected() {
    StandardSip s = new StandardSip().addSonar(1, 100).addSonar(2, 200);
    s.encode(p);
    ArRobotPacket copy = new ArRobotPacket().copyFrom(p);
    StandardSip d = new StandardSip();
    assertFalse(d.decode(truncated(copy, 10)));
    assertFalse(d.decode(truncated(copy, copy.getDataLength() - 1)));
    assertFalse(d.decode(CommandCodecHelper.notASip()));
  }

  @Test
  void configPacketRoundTripsAndKeepsUnknownTail() {
    ArConfigPacket c = new ArConfigPacket();
    c.set(ArConfigPacket.Field.TYPE, "Pioneer").set(ArConfigPacket.Field.SUBTYPE, "p3dx-sh");
    c.set(ArConfigPacket.Field.SERIAL_NUMBER, "SIM").set(ArConfigPacket.Field.NAME, "robbie");
    c.set(ArConfigPacket.Field.ROT_VEL_TOP, 500).set(ArConfigPacket.Field.TRANS_VEL_TOP, 2200);
    c.set(ArConfigPacket.Field.SIP_CYCLE_TIME, 100).set(ArConfigPacket.Field.WATCHDOG, 2000);
    c.set(ArConfigPacket.Field.DRIFT_FACTOR, -123)
        .set(ArConfigPacket.Field.FIRMWARE_VERSION, "S.1");
    c.set(ArConfigPacket.Field.GYRO_CCW, 77);
    c.setExtra(new byte[] {1, 2, 3});
    c.encode(p);
    ArConfigPacket d = ArConfigPacket.decode(p);
    assertEquals(c, d);
    assertEquals("p3dx-sh", d.getSubType());
    assertEquals("S.1", d.getFirmwareVersion());
    assertEquals(-123, d.getInt(ArConfigPacket.Field.DRIFT_FACTOR));
    assertArrayEquals(new byte[] {1, 2, 3}, d.getExtra());
  }

  @Test
  void olderConfigWithoutTheOptionalFieldsDecodes() {
    ArConfigPacket c = new ArConfigPacket();
    c.set(ArConfigPacket.Field.SUBTYPE, "p3at").set(ArConfigPacket.Field.SHUTDOWN_VOLTS, 110);
    c.encode(p);
    int len = 0;
    // find the payload length up to SHUTDOWN_VOLTS by encoding a prefix-only packet
    ArConfigPacket decodedFull = ArConfigPacket.decode(p);
    assertTrue(decodedFull.has(ArConfigPacket.Field.GYRO_CCW));
    ArRobotPacket copy = new ArRobotPacket().copyFrom(p);
    for (int keep = copy.getDataLength(); keep > 0; keep--) {
      ArConfigPacket d = ArConfigPacket.decode(truncated(copy, keep));
      if (d != null && !d.has(ArConfigPacket.Field.FIRMWARE_VERSION)) {
        len = keep;
        assertEquals(110, d.getInt(ArConfigPacket.Field.SHUTDOWN_VOLTS));
        assertEquals("p3at", d.getSubType());
        break;
      }
    }
    assertTrue(len > 0, "a packet ending after SHUTDOWN_VOLTS must decode");
    assertNull(ArConfigPacket.decode(truncated(copy, 20)));
  }

  @Test
  void encoderPacketRoundTripsNegativeCounts() {
    new EncoderPacket(-5, 0x12345678).encode(p);
    assertEquals(new EncoderPacket(-5, 0x12345678), EncoderPacket.decode(p));
    // low 16 bits first, then high 16 bits
    assertEquals((byte) 0xFB, p.getBuf()[4]);
    assertEquals((byte) 0xFF, p.getBuf()[7]);
    assertNull(EncoderPacket.decode(truncated(p, 6)));
  }

  @Test
  void ioPacketRoundTrips() {
    IoPacket io = new IoPacket(new int[] {1, 2, 3, 4}, new int[] {9}, new int[] {0, 512, 1023});
    io.encode(p);
    assertEquals(io, IoPacket.decode(p));
    assertNull(IoPacket.decode(truncated(p, p.getDataLength() - 1)));
  }

  @Test
  void smallPacketsRoundTrip() {
    JoystickPacket j = new JoystickPacket(1, 0, 512, 1000, 3);
    j.encode(p);
    assertEquals(j, JoystickPacket.decode(p));
    GripperPacket g = new GripperPacket(1, GripState.NOT_OPEN | GripState.LIFT_MOVING, 10);
    g.encode(p);
    assertEquals(g, GripperPacket.decode(p));
    GyroPacket gy = new GyroPacket(new int[] {512, 600}, new int[] {30, 31});
    gy.encode(p);
    assertEquals(gy, GyroPacket.decode(p));
    Tcm2Packet t = new Tcm2Packet(1234, -10, 20, 100, -100, 50, 25, 0, 90, 80, -3);
    t.encode(p);
    assertEquals(t, Tcm2Packet.decode(p));
    for (int port = 1; port <= 3; port++) {
      SerAuxPacket a = new SerAuxPacket(port, new byte[] {(byte) 0x90, 0x50, (byte) 0xFF});
      a.encode(p);
      assertEquals(a, SerAuxPacket.decode(p));
    }
    SimStatPacket s =
        new SimStatPacket(3, 100, 100, 98, 1000, -2000, 0, 45, 1, 2, 3, 100, -4, 5, -6);
    s.encode(p);
    assertEquals(s, SimStatPacket.decode(p));
  }

  @Test
  void decodersRejectOtherIds() {
    new JoystickPacket(0, 0, 0, 0, 0).encode(p);
    assertNull(GripperPacket.decode(p));
    assertNull(EncoderPacket.decode(p));
    assertNull(SimStatPacket.decode(p));
    assertNull(ArConfigPacket.decode(p));
    assertNull(SerAuxPacket.decode(p));
  }

  /** Helpers for packets that are not what a decoder expects. */
  static final class CommandCodecHelper {
    static ArRobotPacket notASip() {
      return new ArRobotPacket(0x20).uByteToBuf(1).finalizePacket();
    }
  }
}
