package org.jaria.connection;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
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
  void packetsStillTravelBothWaysAfterABaudSwitch() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection client = new ArSerialConnection(pty.a.toString(), 9600, Clock.system());
        ArSerialConnection robot = new ArSerialConnection(pty.b.toString(), 9600, Clock.system())) {
      client.open();
      robot.open();
      exchange(client, robot, 1);
      assertEquals("9600", ttySpeed(pty.a));
      // What ARIA does after connecting: HOSTBAUD to the robot, then both sides switch.
      for (int baud : new int[] {38400, 115200}) {
        assertTrue(client.setBaud(baud));
        assertTrue(robot.setBaud(baud));
        assertEquals(baud, client.getBaud());
        assertEquals(String.valueOf(baud), ttySpeed(pty.a), "the tty itself runs at " + baud);
        exchange(client, robot, baud);
      }
      assertEquals(ArDeviceConnection.Status.OPEN, client.getStatus());
    }
  }

  /** A command from the client and a SIP from the robot, each arriving whole and in order. */
  private static void exchange(ArDeviceConnection client, ArDeviceConnection robot, int tag)
      throws IOException {
    byte[] vel = CommandCodec.comInt(new ArRobotPacket(), 11, tag % 1000).toByteArray();
    byte[] pulse = CommandCodec.com(new ArRobotPacket(), 0).toByteArray();
    client.write(vel, 0, vel.length);
    client.write(pulse, 0, pulse.length);
    List<byte[]> atRobot = readPackets(robot, 2);
    assertEquals(2, atRobot.size(), "both commands arrived at " + tag);
    assertArrayEquals(vel, atRobot.get(0));
    assertArrayEquals(pulse, atRobot.get(1));
    byte[] sip =
        new StandardSip().setPos(tag % 30000, 7, 9).encode(new ArRobotPacket()).toByteArray();
    robot.write(sip, 0, sip.length);
    List<byte[]> atClient = readPackets(client, 1);
    assertEquals(1, atClient.size(), "the SIP arrived at " + tag);
    assertArrayEquals(sip, atClient.get(0));
  }

  /** The speed the kernel's terminal layer reports for {@code device}, as stty prints it. */
  private static String ttySpeed(Path device) throws IOException, InterruptedException {
    Process p =
        new ProcessBuilder("stty", "-F", device.toRealPath().toString(), "speed")
            .redirectErrorStream(true)
            .start();
    String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim();
    assertTrue(p.waitFor(10, TimeUnit.SECONDS), "stty ended");
    assertEquals(0, p.exitValue(), "stty: " + out);
    return out;
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
