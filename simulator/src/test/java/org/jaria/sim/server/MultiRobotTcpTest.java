package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/** Several robots in one world, each on its own TCP port: base, base + 1, ... as MobileSim. */
class MultiRobotTcpTest {

  /** A port p such that p, p + 1 and p + 2 were all free a moment ago; -1 if none found. */
  private static int freePortRun() throws IOException {
    for (int attempt = 0; attempt < 20; attempt++) {
      int base;
      try (ServerSocket probe = new ServerSocket(0)) {
        base = probe.getLocalPort();
      }
      if (base > 65533) {
        continue;
      }
      if (free(base) && free(base + 1) && free(base + 2)) {
        return base;
      }
    }
    return -1;
  }

  private static boolean free(int port) {
    try (ServerSocket s = new ServerSocket()) {
      s.setReuseAddress(true);
      s.bind(new InetSocketAddress(port));
      return true;
    } catch (IOException taken) {
      return false;
    }
  }

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
  void robotsOnConsecutivePortsAreEachTheirOwnRobot() throws Exception {
    // Another program may take a port between the probe and listen(): try again with new ones.
    for (int attempt = 0; attempt < 5; attempt++) {
      int base = freePortRun();
      assertTrue(base > 0, "no three consecutive free ports");
      SimWorld w = SimWorld.empty(SimOptions.builder().basePort(base).watchdogMillis(0).build());
      SimRobot dx = w.addRobot("p3dx-sh");
      SimRobot at = w.addRobot("p3at-sh");
      try {
        w.listen();
      } catch (IOException taken) {
        w.close();
        continue;
      }
      try (w) {
        check(w, base, dx, at);
      }
      return;
    }
    fail("ports were taken by someone else five times in a row");
  }

  private static void check(SimWorld w, int base, SimRobot dx, SimRobot at) throws Exception {
    assertEquals(base, dx.getPort());
    assertEquals(base + 1, at.getPort());
    w.startRealTime(5);
    try (AriaLikeTcpClient c1 = new AriaLikeTcpClient(base);
        AriaLikeTcpClient c2 = new AriaLikeTcpClient(base + 1)) {
      c1.connectLikeAria();
      c2.connectLikeAria();
      assertEquals("p3dx-sh", c1.subtype, "the first port is the first robot");
      assertEquals("p3at-sh", c2.subtype, "the next port is the next robot");
      c1.readUntil(PacketIds.SIP_STOPPED);
      c2.readUntil(PacketIds.SIP_STOPPED);
      await(w, () -> w.connectedClientCount() == 2);

      c1.comInt(ArCommands.ENABLE.getNumber(), 1);
      c1.comInt(ArCommands.VEL.getNumber(), 300);
      c2.comInt(ArCommands.ENABLE.getNumber(), 1);
      c2.comInt(ArCommands.RVEL.getNumber(), 20);
      await(w, () -> dx.getVel() > 250 && at.getRotVel() > 15);
      assertEquals(0, dx.getRotVel(), 1e-9, "each robot got only its own client's commands");
      assertEquals(0, at.getVel(), 1e-9);

      // A robot added while listening takes the next port.
      SimRobot late = w.addRobot("p3dx-sh");
      assertEquals(base + 2, late.getPort());
      try (AriaLikeTcpClient c3 = new AriaLikeTcpClient(base + 2)) {
        c3.connectLikeAria();
        assertEquals("p3dx-sh", c3.subtype);
        c3.readUntil(PacketIds.SIP_STOPPED);
      }
      assertTrue(dx.isClientConnected() && at.isClientConnected(), "the others kept theirs");
    }
  }
}
