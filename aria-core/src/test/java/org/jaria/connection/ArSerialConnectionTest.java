package org.jaria.connection;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.testing.SocatPty;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** jSerialComm against a real pty pair made by socat: real packets both ways. */
class ArSerialConnectionTest {

  @TempDir Path dir;

  /** Reads from {@code c} until {@code n} packets have arrived (or 5 s of real time pass). */
  private static List<byte[]> readPackets(ArDeviceConnection c, int n) throws IOException {
    List<byte[]> got = new ArrayList<>();
    ArRobotPacketReceiver rx = new ArRobotPacketReceiver(new DropCounters("pty"));
    byte[] buf = new byte[512];
    long end = System.nanoTime() + 5_000_000_000L;
    while (got.size() < n && System.nanoTime() < end) {
      int k = c.read(buf, 0, buf.length, 100);
      if (k > 0) {
        rx.feed(buf, 0, k, System.nanoTime(), p -> got.add(p.toByteArray()));
      }
    }
    return got;
  }

  @Test
  void packetsTravelBothWaysThroughARealTty() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection client = new ArSerialConnection(pty.a.toString(), 9600, Clock.system());
        ArSerialConnection robot = new ArSerialConnection(pty.b.toString(), 9600, Clock.system())) {
      client.open();
      robot.open();
      byte[] enable = CommandCodec.comInt(new ArRobotPacket(), 4, 1).toByteArray();
      byte[] vel = CommandCodec.comInt(new ArRobotPacket(), 11, -200).toByteArray();
      client.write(enable, 0, enable.length);
      client.write(vel, 0, vel.length);
      List<byte[]> atRobot = readPackets(robot, 2);
      assertEquals(2, atRobot.size());
      assertArrayEquals(enable, atRobot.get(0));
      assertArrayEquals(vel, atRobot.get(1));

      StandardSip sip = new StandardSip().setPos(10, 20, 30);
      for (int i = 0; i < 16; i++) {
        sip.addSonar(i, 100 * i);
      }
      byte[] sipBytes = sip.encode(new ArRobotPacket()).toByteArray();
      for (int i = 0; i < 5; i++) {
        robot.write(sipBytes, 0, sipBytes.length);
      }
      List<byte[]> atClient = readPackets(client, 5);
      assertEquals(5, atClient.size());
      assertArrayEquals(sipBytes, atClient.get(4));
      assertTrue(client.getTimeRead() > 0);
    }
  }

  @Test
  void baudCanBeSwitchedWhileOpen() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection c = new ArSerialConnection(pty.a.toString(), 9600, Clock.system())) {
      c.open();
      assertTrue(c.setBaud(38400));
      assertEquals(38400, c.getBaud());
    }
  }

  @Test
  void portIsExclusiveUntilClosed() throws Exception {
    try (SocatPty pty = new SocatPty(dir)) {
      ArSerialConnection first = new ArSerialConnection(pty.a.toString(), 9600, Clock.system());
      first.open();
      ArSerialConnection second = new ArSerialConnection(pty.a.toString(), 9600, Clock.system());
      IOException e = assertThrows(IOException.class, second::open);
      assertTrue(e.getMessage().contains("no other program"), e.getMessage());
      assertEquals(ArDeviceConnection.Status.OPEN_FAILED, second.getStatus());
      first.close();
      second.open();
      assertEquals(ArDeviceConnection.Status.OPEN, second.getStatus());
      second.close();
    }
  }

  @Test
  void missingPortGivesAnActionableMessage() {
    ArSerialConnection c =
        new ArSerialConnection("/dev/does-not-exist-jaria", 9600, Clock.system());
    IOException e = assertThrows(IOException.class, c::open);
    assertTrue(e.getMessage().contains("/dev/does-not-exist-jaria"), e.getMessage());
    assertEquals(e.getMessage(), c.getOpenMessage());
  }
}
