package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.sim.server.ArcosSession;
import org.jaria.sim.server.AriaLikeTcpClient;
import org.junit.jupiter.api.Test;

/**
 * "No memory left behind": after fifty TCP clients come and go, the running world holds on to none
 * of their sessions or connections.
 */
class SessionMemoryTest {

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

  private static ArcosSession currentSession(SimWorld w) {
    w.lock.lock();
    try {
      return w.slots().get(0).session();
    } finally {
      w.lock.unlock();
    }
  }

  /** Runs the collector until every reference is cleared (at most 20 full collections). */
  private static int uncollected(List<WeakReference<Object>> refs) {
    int left = refs.size();
    for (int attempt = 0; attempt < 20 && left > 0; attempt++) {
      System.gc();
      left = (int) refs.stream().filter(r -> r.get() != null).count();
    }
    return left;
  }

  @Test
  void fiftyTcpSessionsLeaveNoSessionObjectBehind() throws Exception {
    try (SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build())) {
      SimRobot robot = w.addRobot("p3dx-sh");
      w.listen();
      w.startRealTime(5);
      List<WeakReference<Object>> perSession = new ArrayList<>();
      for (int i = 0; i < 50; i++) {
        try (AriaLikeTcpClient c = new AriaLikeTcpClient(robot.getPort())) {
          c.connectLikeAria();
          c.readUntil(PacketIds.SIP_STOPPED);
          ArcosSession s = currentSession(w);
          assertNotNull(s, "the SIP came from a session");
          perSession.add(new WeakReference<>(s));
          perSession.add(new WeakReference<>(s.connection()));
          if (i % 2 == 0) {
            c.comInt(ArCommands.CLOSE.getNumber(), 1); // half say goodbye, half vanish
          }
        }
        await(w, () -> !robot.isClientConnected());
      }
      assertEquals(50, robot.getSessionCount());
      assertNull(currentSession(w));
      assertTrue(w.isRealTime(), "the world is still running while we look");
      assertEquals(0, uncollected(perSession), "sessions or connections still reachable");
    }
  }
}
