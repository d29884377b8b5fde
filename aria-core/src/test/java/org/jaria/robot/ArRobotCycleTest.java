package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Collectors;
import org.jaria.clock.Clock;
import org.jaria.connection.ArTcpConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/** The sync cycle: order, isolation, handlers, the lock budget, threads. */
class ArRobotCycleTest {

  @Test
  void branchesRunInARIAsOrderAndTasksByPosition() {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    List<String> order = new ArrayList<>();
    rig.robot.addUserTask("user low", 10, () -> order.add("user low"));
    rig.robot.addUserTask("user high", 90, () -> order.add("user high"));
    rig.robot.addSensorInterpTask("sensor", 5, () -> order.add("sensor"));
    rig.robot.addPacketHandler(
        p -> {
          if (PacketIds.isStandardSip(p.getID())) {
            order.add("handler");
          }
          return false;
        },
        ArListPos.FIRST);
    rig.run(100);
    assertEquals(List.of("handler", "sensor", "user high", "user low"), order);
    assertTrue(rig.robot.remUserTask("user high"));
    order.clear();
    rig.run(100);
    assertEquals(List.of("handler", "sensor", "user low"), order);
  }

  @Test
  void aThrowingTaskIsDisabledAndTheOthersKeepRunning() {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    AtomicInteger good = new AtomicInteger();
    ArSyncTask bad =
        rig.robot.addUserTask(
            "bad",
            50,
            () -> {
              throw new IllegalStateException("student bug");
            });
    rig.robot.addUserTask("good", 10, good::incrementAndGet);
    rig.run(500);
    assertEquals(ArSyncTask.State.FAILURE, bad.getState());
    assertEquals(5, good.get());
    assertTrue(rig.robot.isConnected());
  }

  @Test
  void aFirstHandlerCanTakeSipsAwayFromTheRobot() {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    rig.run(200);
    rig.robot.addPacketHandler(p -> PacketIds.isStandardSip(p.getID()), ArListPos.FIRST);
    double x = rig.robot.getX();
    rig.sip.setPos(900, 0, 0);
    rig.run(300);
    assertEquals(x, rig.robot.getX(), 1e-9, "the robot never saw the SIPs");
  }

  @Test
  void userCodeHoldingTheLockSkipsTasksButKeepsTheRobotAlive() throws Exception {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    rig.robot.setCycleTime(20); // the lock budget is one cycle time
    AtomicInteger runs = new AtomicInteger();
    rig.robot.addUserTask("count", 1, runs::incrementAndGet);
    CountDownLatch locked = new CountDownLatch(1);
    CountDownLatch release = new CountDownLatch(1);
    Thread holder =
        new Thread(
            () -> {
              rig.robot.lock();
              try {
                locked.countDown();
                release.await(30, TimeUnit.SECONDS);
              } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
              } finally {
                rig.robot.unlock();
              }
            },
            "test-lock-holder");
    holder.start();
    assertTrue(locked.await(10, TimeUnit.SECONDS));
    rig.fake.clearReceived();
    rig.run(1500);
    assertEquals(0, runs.get());
    assertTrue(rig.robot.getSkippedCycleCount() > 0, "the skipped cycles were counted");
    assertFalse(rig.fake.received(ArCommands.PULSE).isEmpty(), "pulses while the lock is held");
    release.countDown();
    holder.join(10_000);
    rig.run(200);
    assertTrue(runs.get() > 0);
  }

  @Test
  void cycleTimeMustBePositive() {
    assertThrows(IllegalArgumentException.class, () -> new ArRobot().setCycleTime(0));
  }

  /** Serves one client as a fake robot sending SIPs every 100 ms (real time). */
  private static Thread serveOnce(ServerSocket server) {
    Thread t =
        new Thread(
            () -> {
              try (Socket s = server.accept()) {
                FakeRobot fake =
                    new FakeRobot(ArTcpConnection.wrap(s, Clock.system()), Clock.system());
                StandardSip sip = new StandardSip();
                long next = 0;
                while (fake.pumpWait(10)) {
                  if (fake.isOpen() && System.nanoTime() > next) {
                    fake.sendSip(sip);
                    next = System.nanoTime() + 100_000_000L;
                  }
                }
              } catch (IOException e) {
                // the client went away
              }
            },
            "test-robot-side");
    t.start();
    return t;
  }

  @Test
  void runAsyncCloseLeavesNoThreadBehind() throws Exception {
    Set<String> before = threadNames();
    for (boolean connectFirst : new boolean[] {true, false}) {
      try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
        Thread robotSide = serveOnce(server);
        ArRobot robot = new ArRobot("leak-" + connectFirst);
        robot.setDeviceConnection(
            new ArTcpConnection("127.0.0.1", server.getLocalPort(), Clock.system()));
        CountDownLatch cycled = new CountDownLatch(3);
        robot.addUserTask(
            "count",
            1,
            () -> {
              if (robot.isConnected()) {
                cycled.countDown();
              }
            });
        if (connectFirst) {
          assertTrue(robot.blockingConnect(), robot.getConnectFailure());
          robot.runAsync(true);
        } else {
          robot.runAsync(false);
          assertTrue(robot.blockingConnect(), robot.getConnectFailure()); // made by the cycle
        }
        assertTrue(cycled.await(10, TimeUnit.SECONDS));
        robot.close();
        assertFalse(robot.isRunning());
        robotSide.join(10_000);
        assertFalse(robotSide.isAlive(), "the robot side saw the client close");
      }
    }
    Set<String> after = threadNames();
    after.removeAll(before);
    assertEquals(
        Set.of(), after.stream().filter(n -> n.startsWith("ArRobot-")).collect(Collectors.toSet()));
  }

  private static Set<String> threadNames() {
    return Thread.getAllStackTraces().keySet().stream()
        .filter(Thread::isAlive)
        .map(Thread::getName)
        .collect(Collectors.toSet());
  }
}
