package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.RawClient;
import org.jaria.net.server.modes.ArServerModes;
import org.junit.jupiter.api.Test;

/**
 * A stop is never lost, however fast a client sends (ARIA's clientDemo sends about 900 {@code
 * ratioDrive} a second while a key is held): the flood collapses to its newest request, a stop is
 * applied at the robot's next cycle, and nothing is refused as busy.
 */
class StopIsNeverLostTest {

  /** ratioDrive as ARIA's ArClientRatioDrive sends it: trans, rot, throttle, lateral. */
  static byte[] ratioDrive(int command, double trans, double rot) {
    ArNetPacket p = new ArNetPacket(command);
    p.doubleToBuf(trans).doubleToBuf(rot).doubleToBuf(100).doubleToBuf(0);
    return p.toWire();
  }

  private static String mode(GuiRig rig) {
    return ArServerModes.of(rig.gui.getServer()).getMode();
  }

  /** Waits until the server has read {@code n} more requests than {@code before}. */
  private static void awaitRequests(ArServerBase s, long before, int n) {
    Eventually.until(n + " requests read", () -> s.getStats().getRequests() >= before + n);
  }

  @Test
  void aStopAfterFiveHundredRatioDrivesStopsTheRobotAtOnce() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b);
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      int drive = s.findCommandFromName("ratioDrive");
      int stop = s.findCommandFromName("stop");
      aria.login("", null);
      // Driving at half speed for three seconds, a command every cycle.
      for (int i = 0; i < 30; i++) {
        long before = s.getStats().getRequests();
        aria.send(ratioDrive(drive, 50, 0));
        awaitRequests(s, before, 1);
        rig.run(100);
      }
      assertTrue(rig.robot.getVel() > 600, "driving: " + rig.robot.getVel());
      // The repro: 500 ratioDrive then stop, in one burst, faster than any cycle.
      ByteArrayOutputStream burst = new ByteArrayOutputStream();
      for (int i = 0; i < 500; i++) {
        burst.writeBytes(ratioDrive(drive, 50, 0));
      }
      burst.writeBytes(new ArNetPacket(stop).toWire());
      long before = s.getStats().getRequests();
      aria.send(burst.toByteArray());
      awaitRequests(s, before, 501);
      rig.run(100);
      assertEquals("Stop", mode(rig), "the stop was applied at the next cycle");
      assertTrue(
          rig.runUntil(() -> Math.abs(rig.robot.getVel()) < 5, 5000),
          "and the robot brakes to a halt: " + rig.robot.getVel() + " mm/s");
      assertEquals(0, s.getStats().getBusy(), "nothing was refused as busy");
      assertEquals(0, s.getStats().getRequestErrors());
      assertTrue(s.getStats().getSuperseded() >= 499, "the flood collapsed");
      rig.run(3000);
      assertEquals("Stop", mode(rig), "no request from before the stop restarts the robot");
      assertTrue(Math.abs(rig.robot.getVel()) < 5);
    }
  }

  @Test
  void aFloodOfRatioDrivesIsAppliedAsItsNewestRequest() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b);
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      int drive = s.findCommandFromName("ratioDrive");
      aria.login("", null);
      ByteArrayOutputStream burst = new ByteArrayOutputStream();
      for (int i = 0; i < 900; i++) {
        burst.writeBytes(ratioDrive(drive, 50, 0));
      }
      burst.writeBytes(ratioDrive(drive, -40, 0));
      long before = s.getStats().getRequests();
      aria.send(burst.toByteArray());
      awaitRequests(s, before, 901);
      assertEquals(1, s.getPendingCycleCommands(), "901 requests, one waiting");
      rig.run(1500);
      assertEquals("Drive", mode(rig));
      assertTrue(rig.robot.getVel() < -100, "the newest, backwards: " + rig.robot.getVel());
      assertEquals(0, s.getStats().getBusy());
    }
  }

  @Test
  void aStopBehindAFullQueueJumpsIt() throws Exception {
    ServerOptions o =
        ServerOptions.builder()
            .port(0)
            .minInterval(Duration.ofMillis(20))
            .cycleQueue(8)
            .maxCommandsPerCycle(1)
            .maxPendingCalls(64)
            .build();
    try (GuiRig rig = GuiRig.plain(b -> b.options(o));
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      aria.login("", null);
      int wander = s.findCommandFromName("wander");
      ByteArrayOutputStream burst = new ByteArrayOutputStream();
      for (int i = 0; i < 20; i++) {
        burst.writeBytes(new ArNetPacket(wander).toWire());
      }
      burst.writeBytes(new ArNetPacket(s.findCommandFromName("stop")).toWire());
      long before = s.getStats().getRequests();
      aria.send(burst.toByteArray());
      awaitRequests(s, before, 21);
      assertEquals(12, s.getStats().getBusy(), "wanders beyond the queue's 8 were refused");
      rig.run(100);
      assertEquals("Stop", mode(rig), "the stop did not wait 8 cycles behind the wanders");
      assertEquals(0, s.getPendingCycleCommands());
    }
  }

  @Test
  void aJariaClientGetsAnAnswerForEverySupersededRequest() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      List<CompletableFuture<ArNetPacket>> sent = new ArrayList<>();
      for (int i = 0; i < 200; i++) {
        sent.add(rig.client.requestOnce("ratioDrive", 30.0, 0.0, 100.0));
      }
      rig.await(sent.get(sent.size() - 1));
      for (CompletableFuture<ArNetPacket> f : sent) {
        rig.await(f);
      }
      assertTrue(rig.gui.getServer().getStats().getSuperseded() > 0);
      assertEquals(0, rig.gui.getServer().getStats().getBusy());
    }
  }
}
