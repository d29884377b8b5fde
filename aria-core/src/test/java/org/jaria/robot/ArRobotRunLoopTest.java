package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.clock.VirtualClock;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The robot's own run loop ({@link ArRobot#runAsync}) on a virtual clock: the test plays the robot
 * side and moves time, and uses {@link VirtualClock#awaitWaiters} to know the cycle thread has
 * parked before it does. Real time only bounds how long a broken test may hang.
 */
class ArRobotRunLoopTest {

  private static final Duration PATIENCE = Duration.ofSeconds(10);
  private static final long MS = 1_000_000L;

  private final LockstepRig rig = new LockstepRig();
  private final VirtualClock clock = rig.clock;
  private final ArRobot robot = rig.robot;

  /** Virtual time of every cycle the robot ran, as its user task saw it. */
  private final BlockingQueue<Long> cycles = new LinkedBlockingQueue<>();

  @AfterEach
  void tearDown() {
    robot.close();
  }

  /** Connects in lockstep, then leaves the robot with nothing unread and no SIPs coming. */
  private void connectQuietly() {
    assertTrue(rig.connect());
    rig.run(300);
    rig.sendSips = false;
    robot.addUserTask("record", 1, () -> cycles.add(clock.nanoTime()));
  }

  private void awaitParked() throws InterruptedException {
    assertTrue(clock.awaitWaiters(1, PATIENCE), "the cycle thread parks on the clock");
  }

  private long nextCycle() throws InterruptedException {
    Long t = cycles.poll(PATIENCE.toSeconds(), TimeUnit.SECONDS);
    assertTrue(t != null, "a cycle ran");
    return t;
  }

  @Test
  void chainedCycleRunsOnEachSipAndFallsBackAfterTwoCycleTimes() throws Exception {
    connectQuietly();
    long t0 = clock.nanoTime();
    robot.runAsync(false);
    awaitParked();
    assertEquals(t0 + 200 * MS, clock.nextDeadline(), "waits for a SIP at most two cycle times");

    rig.fake.sendSip(rig.sip);
    assertEquals(t0, nextCycle(), "a SIP starts a cycle at once");

    awaitParked();
    clock.advanceMillis(199);
    assertNull(cycles.poll(), "no SIP and less than two cycle times: no cycle");
    clock.advanceMillis(1);
    assertEquals(t0 + 200 * MS, nextCycle(), "the fallback after two cycle times");

    awaitParked();
    assertEquals(t0 + 400 * MS, clock.nextDeadline());
    clock.advanceMillis(50);
    rig.sip.setPos(700, 0, 0);
    rig.fake.sendSip(rig.sip);
    assertEquals(t0 + 250 * MS, nextCycle());
    assertEquals(700, robot.getX(), 1e-9, "the SIP that started the cycle was used in it");
    assertTrue(robot.isRunning());
  }

  @Test
  void unchainedCycleRunsEveryCycleTimeWhateverTheSips() throws Exception {
    connectQuietly();
    robot.setCycleChained(false);
    long t0 = clock.nanoTime();
    robot.runAsync(false);
    awaitParked();
    assertEquals(t0 + 100 * MS, clock.nextDeadline(), "sleeps one cycle time");

    rig.sip.setPos(500, 0, 0);
    rig.fake.sendSip(rig.sip);
    assertNull(cycles.poll(), "a SIP does not wake an unchained cycle");
    assertEquals(1, clock.waitingCount());
    clock.advanceMillis(100);
    assertEquals(t0 + 100 * MS, nextCycle());
    assertEquals(500, robot.getX(), 1e-9, "the SIP waiting in the connection was read");

    awaitParked();
    clock.advanceMillis(100);
    assertEquals(t0 + 200 * MS, nextCycle(), "and again without any SIP");

    awaitParked();
    robot.stopRunning(); // wakes the sleeping cycle: no time needs to pass
    robot.waitForRunExit();
    assertFalse(robot.isRunning());
    assertNull(cycles.poll(), "stopping does not run another cycle");
  }

  @Test
  void runExitCallbacksRunOnTheCycleThreadWhenTheLoopEnds() throws Exception {
    connectQuietly();
    List<String> exits = new CopyOnWriteArrayList<>();
    CountDownLatch exited = new CountDownLatch(1);
    robot.addRunExitCB(
        () -> {
          exits.add(Thread.currentThread().getName());
          exited.countDown();
        });
    robot.runAsync(true);
    awaitParked();
    robot.disconnect(); // the waiting read sees the closed pipe; not connected, so the loop ends
    assertTrue(exited.await(PATIENCE.toSeconds(), TimeUnit.SECONDS));
    robot.waitForRunExit();
    assertFalse(robot.isRunning());
    assertEquals(List.of("ArRobot-rig"), exits);

    Runnable removed = () -> exits.add("removed");
    robot.addRunExitCB(removed);
    robot.remRunExitCB(removed);
    robot.setCycleChained(false);
    robot.runAsync(false);
    awaitParked();
    robot.stopRunning();
    robot.waitForRunExit();
    assertEquals(List.of("ArRobot-rig", "ArRobot-rig"), exits, "once per run, removed one gone");
  }

  @Test
  void asyncConnectReturnsAtOnceAndTheRunningCycleMakesTheConnection() throws Exception {
    List<String> connectedOn = new CopyOnWriteArrayList<>();
    CountDownLatch connected = new CountDownLatch(1);
    robot.addConnectCB(
        () -> {
          connectedOn.add(Thread.currentThread().getName());
          connected.countDown();
        });
    robot.runAsync(false);
    awaitParked();
    assertTrue(robot.asyncConnect());
    assertTrue(robot.isConnecting(), "under way, not done");
    assertFalse(robot.isConnected());
    assertTrue(robot.asyncConnect(), "asking again while connecting is harmless");

    // Play the robot side: answer what arrived, send SIPs once open, let 10 ms pass.
    long sinceSip = 0;
    for (int step = 0; step < 3000 && connected.getCount() > 0; step++) {
      awaitParked();
      rig.fake.pump();
      sinceSip += 10;
      if (rig.fake.isOpen() && sinceSip >= 100) {
        sinceSip = 0;
        rig.fake.sendSip(rig.sip);
      }
      clock.advanceMillis(10);
    }
    assertTrue(connected.await(PATIENCE.toSeconds(), TimeUnit.SECONDS), robot.getConnectFailure());
    assertTrue(robot.isConnected());
    assertEquals(List.of("ArRobot-rig"), connectedOn, "the cycle thread made the connection");
    assertTrue(rig.fake.isOpen());
    assertFalse(rig.fake.received(ArCommands.CONFIG).isEmpty(), "the handshake asked CONFIG");
  }

  @Test
  void asyncConnectWithoutAConnectionFailsAtOnce() {
    ArRobot lonely = new ArRobot("lonely", clock, true);
    AtomicInteger failed = new AtomicInteger();
    lonely.addFailedConnectCB(failed::incrementAndGet);
    assertFalse(lonely.asyncConnect());
    assertFalse(lonely.isConnecting());
    assertEquals(1, failed.get());
    assertTrue(lonely.getConnectFailure().contains("setDeviceConnection"));
  }

  @Test
  void asyncConnectToADeadRobotFailsOnVirtualTime() {
    rig.fake.answerSync(false);
    AtomicInteger failed = new AtomicInteger();
    robot.addFailedConnectCB(failed::incrementAndGet);
    assertTrue(robot.asyncConnect());
    assertTrue(rig.runUntil(() -> !robot.isConnecting(), 60_000), "gives up in bounded time");
    assertFalse(robot.isConnected());
    assertEquals(1, failed.get());
    assertFalse(robot.getConnectFailure().isEmpty());
    List<FakeRobot.Received> syncs = rig.fake.received(ArCommands.PULSE);
    assertTrue(syncs.size() >= 5, "SYNC0 was retried: " + syncs.size());
  }

  @Test
  void aCycleLongerThanTheWarningTimeIsCounted() {
    assertTrue(rig.connect());
    robot.setCycleWarningTime(250);
    AtomicInteger slowRuns = new AtomicInteger();
    robot.addUserTask(
        "slow",
        1,
        () -> {
          if (slowRuns.getAndIncrement() == 0) {
            clock.advanceMillis(300); // this cycle takes 300 ms of robot time
          } else {
            clock.advanceMillis(200);
          }
        });
    rig.run(100);
    assertEquals(1, robot.getCycleOverrunCount(), "only the 300 ms cycle overran");
    rig.run(300);
    assertEquals(1, robot.getCycleOverrunCount(), "200 ms cycles are within 250 ms");
    assertTrue(robot.getDiagnostics().contains("overruns 1"), robot.getDiagnostics());
    robot.setCycleWarningTime(0);
    robot.remUserTask("slow");
    robot.addUserTask("slower", 1, () -> clock.advanceMillis(1000));
    rig.run(300);
    assertEquals(1, robot.getCycleOverrunCount(), "warning time 0: never");
  }

  @Test
  void disableMotorsSendsEnableZero() {
    assertTrue(rig.connect());
    rig.fake.clearReceived();
    assertTrue(robot.enableMotors());
    assertTrue(robot.disableMotors());
    rig.run(10);
    List<FakeRobot.Received> enables = rig.fake.received(ArCommands.ENABLE);
    assertEquals(2, enables.size());
    assertEquals(1, enables.get(0).intArg());
    assertEquals(0, enables.get(1).intArg());
    assertEquals("FA FB 06 04 3B 00 00 04 3B", enables.get(1).hex(), "ENABLE 0 on the wire");

    rig.sip.setFlags(1); // the robot says its motors are on ...
    rig.run(200);
    assertTrue(robot.areMotorsEnabled());
    robot.disableMotors();
    rig.sip.setFlags(0); // ... and off after ENABLE 0
    rig.run(200);
    assertFalse(robot.areMotorsEnabled());
  }

  @Test
  void eachSipRunsExactlyOneCycle() throws IOException, InterruptedException {
    connectQuietly();
    StandardSip sip = rig.sip;
    robot.runAsync(false);
    awaitParked();
    for (int i = 1; i <= 5; i++) {
      sip.setPos(100 * i, 0, 0);
      rig.fake.sendSip(sip);
      nextCycle();
      awaitParked();
      assertEquals(100 * i, robot.getX(), 1e-9);
    }
    assertNull(cycles.poll(), "one cycle per SIP");
  }
}
