package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import org.jaria.action.ArActionDesired;
import org.jaria.clock.Clock;
import org.jaria.clock.VirtualClock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The state reflector decides under its monitor and writes without it: a slow write never keeps
 * another thread from its getters and setters, and commands still leave in the order they were
 * decided.
 */
class StateReflectorTest {

  private final VirtualClock clock = new VirtualClock();
  private final Wire wire = new Wire(clock);
  private final ArRobotPacketSender sender = new ArRobotPacketSender(clock);
  private final RobotStatus still = RobotStatus.initial(List.of());

  StateReflectorTest() {
    sender.setDeviceConnection(wire);
  }

  private StateReflector reflector(boolean doStateReflection) {
    StateReflector r = new StateReflector(clock, sender, () -> still);
    r.setDoStateReflection(doStateReflection);
    r.reset();
    wire.watched = r;
    return r;
  }

  @Test
  void nothingIsWrittenHoldingTheMonitor() {
    StateReflector reflecting = reflector(true);
    reflecting.setVel(300);
    clock.advanceMillis(100);
    reflecting.reflect(new ArActionDesired()); // the cycle: limits and VEL
    reflecting.stop();
    StateReflector direct = reflector(false);
    direct.setVel(200); // sent at once
    direct.setRotVel(10);
    direct.move(500);

    assertTrue(wire.commands.contains(ArCommands.VEL.getNumber()), wire.commands.toString());
    assertTrue(wire.commands.contains(ArCommands.STOP.getNumber()), wire.commands.toString());
    assertTrue(wire.commands.contains(ArCommands.MOVE.getNumber()), wire.commands.toString());
    assertEquals(wire.commands.size(), wire.heldMonitor.size());
    assertFalse(
        wire.heldMonitor.contains(true),
        "a command was written while holding the reflector's monitor: " + wire.heldMonitor);
  }

  @Test
  @Timeout(60) // guards against a hang if the design regresses; never reached when it works
  void whileTheCycleWritesOthersGoOnAndAStopStillLeavesAfterTheCycle() throws Exception {
    StateReflector r = reflector(true);
    r.setVel(300);
    clock.advanceMillis(100);
    CountDownLatch writing = new CountDownLatch(1);
    CountDownLatch release = new CountDownLatch(1);
    wire.onFirstWrite =
        () -> {
          writing.countDown();
          awaitQuietly(release);
        };
    Thread cycle = new Thread(() -> r.reflect(new ArActionDesired()), "StateReflectorTest-cycle");
    cycle.start();
    writing.await(); // the cycle has decided, and is stuck in its first write

    // Another thread stops the robot: it decides (STOP) and queues behind the cycle's commands.
    Thread stopper = new Thread(r::stop, "StateReflectorTest-stop");
    stopper.start();
    while (stopper.getState() != Thread.State.WAITING && stopper.isAlive()) {
      Thread.onSpinWait(); // until it waits for the writer: its STOP is decided and queued
    }
    // The monitor is free while the cycle writes: getters answer from this thread at once.
    assertTrue(r.isDirectMotion());
    assertTrue(r.isMoveDone(0), "a velocity is no move, so there is none to wait for");

    release.countDown();
    cycle.join();
    stopper.join();
    int vel = wire.commands.indexOf(ArCommands.VEL.getNumber());
    int stop = wire.commands.indexOf(ArCommands.STOP.getNumber());
    assertTrue(vel >= 0 && stop > vel, "VEL 300 was decided first, so it leaves first: " + wire);
    assertEquals(stop, wire.commands.size() - 1, "STOP is the last word: " + wire.commands);
  }

  private static void awaitQuietly(CountDownLatch latch) {
    try {
      latch.await();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /**
   * A connection that records the command of each packet written, and whether the writing thread
   * held the watched reflector's monitor while writing it.
   */
  private static final class Wire implements ArDeviceConnection {
    private final Clock clock;
    final List<Integer> commands = new CopyOnWriteArrayList<>();
    final List<Boolean> heldMonitor = new CopyOnWriteArrayList<>();
    volatile StateReflector watched;
    volatile Runnable onFirstWrite;

    Wire(Clock clock) {
      this.clock = clock;
    }

    @Override
    public void open() {}

    @Override
    public Status getStatus() {
      return Status.OPEN;
    }

    @Override
    public String getOpenMessage() {
      return "";
    }

    @Override
    public int read(byte[] buf, int off, int len, long timeoutMs) {
      return 0;
    }

    @Override
    public void write(byte[] buf, int off, int len) throws IOException {
      heldMonitor.add(Thread.holdsLock(watched));
      commands.add(buf[off + 3] & 0xFF); // 0xFA 0xFB, length, command
      Runnable first = onFirstWrite;
      if (first != null) {
        onFirstWrite = null;
        first.run();
      }
    }

    @Override
    public void close() {}

    @Override
    public long getTimeRead() {
      return 0;
    }

    @Override
    public Clock clock() {
      return clock;
    }

    @Override
    public String getPortName() {
      return "wire";
    }

    @Override
    public String toString() {
      return commands.toString();
    }
  }
}
