package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;
import org.jaria.clock.VirtualClock;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.Hex;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/** The real TCP server, driven by a client that behaves like ARIA, on a real-time world. */
class TcpServerTest {

  private static SimWorld startWorld(double speedup) throws IOException {
    SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build());
    w.addRobot("p3dx-sh");
    w.listen();
    w.startRealTime(speedup);
    return w;
  }

  /** Waits (bounded) until {@code cond} holds, checked by the world thread after each tick. */
  private static void await(SimWorld w, BooleanSupplier cond) throws InterruptedException {
    CountDownLatch latch = new CountDownLatch(1);
    Runnable check =
        () -> {
          if (cond.getAsBoolean()) {
            latch.countDown();
          }
        };
    w.addStepListener(check);
    try {
      assertTrue(latch.await(10, TimeUnit.SECONDS), "condition never became true");
    } finally {
      w.removeStepListener(check);
    }
  }

  @Test
  void ariaHandshakeDriveAndSonarOverTcp() throws Exception {
    try (SimWorld w = startWorld(1)) {
      SimRobot robot = w.getRobot(0);
      int port = robot.getPort();
      assertTrue(port > 0);
      try (AriaLikeTcpClient c = new AriaLikeTcpClient(port)) {
        c.writeRaw(Hex.parse("FA FB 03 00 00 00"));
        assertEquals("FA FB 03 00 00 00", Hex.format(c.readFrame()));
        c.writeRaw(Hex.parse("FA FB 03 01 00 01"));
        assertEquals("FA FB 03 01 00 01", Hex.format(c.readFrame()));
        c.writeRaw(Hex.parse("FA FB 03 02 00 02"));
        byte[] sync2 = c.readFrame();
        ArRobotPacket expected = new ArRobotPacket(ArCommands.SYNC2);
        expected.strToBuf("MobileSim").strToBuf("Pioneer").strToBuf("p3dx-sh").finalizePacket();
        assertArrayEquals(expected.toByteArray(), sync2);

        c.comInt(ArCommands.OPEN, 1);
        ArRobotPacket first = c.readUntil(PacketIds.SIP_STOPPED);
        StandardSip sip = new StandardSip();
        assertTrue(sip.decode(first));
        assertEquals(0, sip.getFlags() & 1, "motors disabled until ENABLE");
        c.writeRaw(Hex.parse("FA FB 06 04 3B 01 00 05 3B")); // ENABLE 1, the spec's vector
        c.comInt(ArCommands.CONFIG, 1);
        ArConfigPacket cfg = ArConfigPacket.decode(c.readUntil(PacketIds.CONFIG));
        assertNotNull(cfg);
        assertEquals("p3dx-sh", cfg.getSubType());
        assertEquals("SIM", cfg.getSerialNumber());

        c.comInt(ArCommands.VEL, 200);
        c.comInt(ArCommands.RVEL, 10);
        boolean moving = false;
        boolean sonar = false;
        for (int i = 0; i < 60 && !(moving && sonar); i++) {
          ArRobotPacket p = c.readUntil(PacketIds.SIP_MOVING);
          assertTrue(sip.decode(p));
          moving |= sip.getLeftVel() > 150 && sip.getRightVel() > sip.getLeftVel();
          sonar |= sip.getSonarCount() > 0;
          c.com(ArCommands.PULSE); // as ARIA does when idle
        }
        assertTrue(moving, "the robot drives as commanded");
        assertTrue(sonar, "SIPs carry sonar readings");

        // The same line is taken over by a new program: SYNC0 gets a SIP, CLOSE, start again.
        c.comInt(ArCommands.VEL, 0);
        c.comInt(ArCommands.RVEL, 0);
        await(w, () -> Math.abs(robot.getVel()) < 1e-9 && Math.abs(robot.getRotVel()) < 1e-9);
        c.connectLikeAria();
        assertEquals("MobileSim", c.name);
        assertEquals("Pioneer", c.type);
        assertEquals("p3dx-sh", c.subtype);
        c.readUntil(PacketIds.SIP_STOPPED);
        assertTrue(robot.isSessionOpen());

        c.comInt(ArCommands.VEL, 300);
        c.comInt(ArCommands.ENABLE, 1);
        c.comInt(ArCommands.VEL, 300);
        await(w, () -> robot.getVel() > 100);
      }
      // The client vanished mid-session without CLOSE: the robot stops, the port is free again.
      await(w, () -> !robot.isClientConnected());
      assertEquals(0, robot.getVel(), 1e-9);
      assertFalse(robot.areMotorsEnabled());
      try (AriaLikeTcpClient again = new AriaLikeTcpClient(port)) {
        again.connectLikeAria();
        assertEquals("p3dx-sh", again.subtype);
        again.readUntil(PacketIds.SIP_STOPPED);
      }
    }
  }

  @Test
  void fiftyConnectCyclesLeaveNoThreadSocketOrSession() throws Exception {
    Set<String> threadsBefore = threadNames();
    long fdBefore = openFiles();
    int port;
    SimRobot robot;
    String worldThread;
    try (SimWorld w = startWorld(5)) {
      robot = w.getRobot(0);
      port = robot.getPort();
      worldThread = "jaria-sim-" + w.getName();
      Set<String> running = threadNames();
      assertTrue(running.contains(worldThread), running + " has " + worldThread);
      long fdRunning = openFiles();
      for (int i = 0; i < 50; i++) {
        try (AriaLikeTcpClient c = new AriaLikeTcpClient(port)) {
          c.connectLikeAria();
          c.readUntil(PacketIds.SIP_STOPPED);
          if (i % 2 == 0) {
            c.comInt(ArCommands.CLOSE, 1); // half of them say goodbye, half vanish
          }
        }
        await(w, () -> !robot.isClientConnected());
      }
      assertEquals(50, robot.getSessionCount());
      assertEquals(0, w.connectedClientCount());
      assertEquals(running, threadNames(), "no thread came or went");
      if (fdRunning >= 0) {
        assertTrue(
            openFiles() <= fdRunning + 5,
            "sockets were closed: " + openFiles() + " vs " + fdRunning);
      }
    }
    assertFalse(threadNames().contains(worldThread), "the world thread ended");
    assertEquals(threadsBefore, threadNames());
    if (fdBefore >= 0) {
      assertTrue(openFiles() <= fdBefore + 5, "every file descriptor released");
    }
    try (ServerSocket s = new ServerSocket()) {
      s.setReuseAddress(true);
      s.bind(new InetSocketAddress(port));
      assertEquals(port, s.getLocalPort(), "the port is free after close");
    }
  }

  @Test
  void aBusyPortGivesAClearError() throws Exception {
    try (ServerSocket taken = new ServerSocket(0);
        SimWorld w = SimWorld.empty(SimOptions.builder().basePort(taken.getLocalPort()).build())) {
      w.addRobot("p3dx-sh");
      IOException e = assertThrows(IOException.class, w::listen);
      assertTrue(e.getMessage().contains(String.valueOf(taken.getLocalPort())), e.getMessage());
      assertTrue(e.getMessage().contains("--port"), e.getMessage());
    }
  }

  @Test
  void aClientThatStopsReadingIsDroppedWithoutBlocking() throws Exception {
    try (ServerSocketChannel server = ServerSocketChannel.open()) {
      server.bind(new InetSocketAddress(java.net.InetAddress.getLoopbackAddress(), 0));
      try (SocketChannel client = SocketChannel.open(server.getLocalAddress())) {
        SocketChannel accepted = server.accept();
        NioSocketConnection conn = new NioSocketConnection(accepted, new VirtualClock());
        byte[] chunk = new byte[1024];
        IOException dropped = null;
        for (int i = 0; i < 20_000 && dropped == null; i++) {
          try {
            conn.write(chunk, 0, chunk.length);
          } catch (IOException e) {
            dropped = e;
          }
        }
        assertNotNull(dropped, "20 MB never read must drop the client");
        assertTrue(dropped.getMessage().contains("stopped reading"), dropped.getMessage());
        assertFalse(accepted.isOpen(), "the simulator closed its end");
        assertEquals(org.jaria.connection.ArDeviceConnection.Status.CLOSED_ERROR, conn.getStatus());
        assertTrue(client.isOpen());
      }
    }
  }

  private static Set<String> threadNames() {
    Set<String> names = new TreeSet<>();
    for (Thread t : Thread.getAllStackTraces().keySet()) {
      if (t.isAlive() && t.getName().startsWith("jaria")) {
        names.add(t.getName());
      }
    }
    return names;
  }

  private static long openFiles() throws IOException {
    Path fd = Path.of("/proc/self/fd");
    if (!Files.isDirectory(fd)) {
      return -1;
    }
    try (Stream<Path> s = Files.list(fd)) {
      return s.count();
    }
  }
}
