package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.sim.RobotFactory;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/**
 * MobileSim's robot factory over real sockets: each client gets its own robot, which leaves the
 * world when the client disconnects; a flood of clients leaves no robot and no thread behind.
 */
class RobotFactoryTcpTest {

  private static void await(SimWorld w, BooleanSupplier cond, String what) throws Exception {
    CountDownLatch latch = new CountDownLatch(1);
    Runnable check =
        () -> {
          if (cond.getAsBoolean()) {
            latch.countDown();
          }
        };
    w.addStepListener(check);
    try {
      assertTrue(latch.await(30, TimeUnit.SECONDS), "never happened: " + what);
    } finally {
      w.removeStepListener(check);
    }
  }

  private static SimWorld officeWithFactory() throws Exception {
    SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build());
    w.addRobotFactory(RobotOptions.of("p3dx-sh"), 0, null);
    w.listen();
    return w;
  }

  @Test
  void eachClientGetsItsOwnRobotWhichLeavesWithIt() throws Exception {
    try (SimWorld w = officeWithFactory()) {
      RobotFactory f = w.getRobotFactories().get(0);
      assertTrue(f.getPort() > 0);
      assertEquals(List.of(), w.getRobots(), "no robot before a client comes");
      w.startRealTime(5);
      try (AriaLikeTcpClient c1 = new AriaLikeTcpClient(f.getPort())) {
        c1.connectLikeAria();
        c1.readUntil(PacketIds.SIP_STOPPED);
        SimRobot r1;
        SimRobot r2;
        try (AriaLikeTcpClient c2 = new AriaLikeTcpClient(f.getPort())) {
          c2.connectLikeAria();
          c2.readUntil(PacketIds.SIP_STOPPED);
          await(w, () -> w.getRobots().size() == 2, "two robots");
          r1 = w.getRobots().get(0);
          r2 = w.getRobots().get(1);
          assertEquals("p3dx-sh", c1.subtype);
          assertEquals("127.0.0.1:" + c1.socket.getLocalPort(), r1.getName(), "named after c1");
          assertEquals("127.0.0.1:" + c2.socket.getLocalPort(), r2.getName(), "named after c2");
          assertEquals(f, r1.getFactory());
          assertNotEquals(r1.getTruePose(), r2.getTruePose(), "the second stands beside the first");
          assertEquals(List.of(r1, r2), f.getRobots());

          c1.comInt(ArCommands.ENABLE.getNumber(), 1);
          c1.comInt(ArCommands.VEL.getNumber(), 200);
          await(w, () -> r1.getVel() > 150, "c1 drives its robot");
          assertEquals(0, r2.getVel(), 1e-9, "c2's robot got none of c1's commands");
        }
        await(w, () -> w.getRobots().size() == 1, "c2's robot gone");
        assertTrue(r2.isRemoved());
        assertEquals(List.of(r1), w.getRobots());
        assertEquals(1, w.snapshot().robots().size());
        assertFalse(r1.isRemoved());
        // c1 keeps running: SIPs keep coming and its robot keeps driving
        c1.readUntil(PacketIds.SIP_MOVING);
        assertTrue(r1.getVel() > 150, "still driving");
        assertTrue(r1.isSessionOpen());
      }
      await(w, () -> w.getRobots().isEmpty(), "c1's robot gone");
      assertEquals(2, f.getRobotsMade());
      assertEquals(List.of(), f.getRobots());
    }
  }

  /** Threads whose name says they belong to the simulator. */
  private static long simThreads() {
    return Thread.getAllStackTraces().keySet().stream()
        .filter(t -> t.isAlive() && t.getName().startsWith("jaria-sim"))
        .count();
  }

  @Test
  void aFloodOfClientsLeavesNoRobotAndNoThread() throws Exception {
    try (SimWorld w = officeWithFactory()) {
      RobotFactory f = w.getRobotFactories().get(0);
      w.startRealTime(0);
      long threadsBefore = simThreads();
      int clients = 60;
      for (int i = 0; i < clients; i++) {
        try (Socket s = new Socket()) {
          s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), f.getPort()), 5000);
          OutputStream out = s.getOutputStream();
          switch (i % 3) {
            case 0 -> {} // connects and leaves at once
            case 1 -> out.write(new byte[] {(byte) 0xFA, (byte) 0xFB, 3, 0, 0, 0}); // SYNC0
            default -> out.write(new byte[] {1, 2, 3, (byte) 0xFA, 9, 9, 9, 9}); // garbage
          }
          out.flush();
        }
      }
      // a few that stay a while, then all leave together
      Socket[] held = new Socket[5];
      for (int i = 0; i < held.length; i++) {
        held[i] = new Socket();
        held[i].connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), f.getPort()));
      }
      await(w, () -> f.getRobotsMade() == clients + held.length, "every client got a robot");
      for (Socket s : held) {
        s.close();
      }
      await(w, () -> w.getRobots().isEmpty(), "zero robots");
      assertEquals(0, w.connectedClientCount());
      assertEquals(List.of(), f.getRobots());
      assertEquals(threadsBefore, simThreads(), "no thread per client");
      assertTrue(w.snapshot().robots().isEmpty());
    }
  }
}
