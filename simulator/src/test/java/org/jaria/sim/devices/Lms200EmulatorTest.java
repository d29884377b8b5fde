package org.jaria.sim.devices;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.jaria.clock.Clock;
import org.jaria.clock.VirtualClock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.ArTcpConnection;
import org.jaria.connection.PipeConnection;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArLMS2xx;
import org.jaria.laser.ArSick;
import org.jaria.laser.LmsSettings;
import org.jaria.laser.LmsTelegram;
import org.jaria.range.LaserScan;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.testing.SocatPty;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;

/**
 * The LMS-200 driver against a simulated robot's laser presented as a real LMS-200 on a serial
 * pseudo-terminal (socat) or a TCP port: the whole set-up conversation, the baud switch, scans that
 * match the world, and the faults of real lasers.
 *
 * <p>Each test has a world, an emulator and a line of its own and waits mostly on the line (9600
 * baud), so the tests run side by side (see junit-platform.properties).
 */
@Execution(ExecutionMode.CONCURRENT)
class Lms200EmulatorTest {

  /** Bound on every wait: generous, so a slow machine is not a failure; never a pacing device. */
  private static final long PATIENCE_MS = 20_000;

  @TempDir Path dir;
  private SimWorld world;
  private SimRobot robot;

  @BeforeEach
  void world() {
    // A 6 m x 4 m room; the robot at its centre facing +x, so the wall ahead is 3 m away.
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(-3000, -2000, 3000, -2000),
            new ArLineSegment(3000, -2000, 3000, 2000),
            new ArLineSegment(3000, 2000, -3000, 2000),
            new ArLineSegment(-3000, 2000, -3000, -2000));
    world = SimWorld.ofLines(walls, new ArPose(0, 0, 0), SimOptions.defaults());
    robot = world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true).withStartPose(ArPose.ORIGIN));
  }

  @AfterEach
  void close() {
    world.close();
  }

  private ArPose laserPose() {
    var m = robot.getModel();
    return new ArPose(m.getLaserX(), m.getLaserY(), m.getLaserTh());
  }

  private static double at(LaserScan s, double angle) {
    for (int i = 0; i < s.size(); i++) {
      if (Math.abs(s.getAngle(i) - angle) < 1e-9) {
        return s.getRange(i);
      }
    }
    throw new AssertionError("no reading at " + angle);
  }

  @Test
  void connectsThroughAPtySwitchesTo38400AndReadsTheWorld() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device = new ArSerialConnection(pty.b.toString(), 9600, Clock.system());
        Lms200Emulator lms =
            Lms200Emulator.start(device, LaserSensor.of(robot), DeviceFaults.NONE, 20);
        ArSick laser = new ArSick("sick", new LmsSettings(180, 0.5, "1mm", 1, 38400))) {
      ArSerialConnection port = new ArSerialConnection(pty.a.toString(), 9600, Clock.system());
      laser.setDeviceConnection(port);
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertEquals(38400, port.getBaud(), "the driver switched the port after the laser did");
      assertEquals(38400, device.getBaud(), "and so did the laser");
      assertTrue(laser.waitForScans(3, PATIENCE_MS), "three scans arrived");
      // The emulator counts a scan once its write returned, so the last one received may not be
      // counted yet.
      assertTrue(lms.getScansSent() >= 2);
      LaserScan s = laser.getLaserScan();
      assertEquals(361, s.size());
      ArPose mount = laserPose();
      // Ahead: the wall at x = 3000, seen from the laser's mounting point.
      assertEquals(3000 - mount.x(), at(s, 0), 1.0);
      // Left: the wall at y = 2000.
      assertEquals(2000 - mount.y(), at(s, 90), 1.0);
      assertEquals(2000 + mount.y(), at(s, -90), 1.0);
      // Polar query of the range device: the closest obstacle in front, from the robot's centre.
      laser.setSensorPosition(mount.x(), mount.y(), mount.th());
      assertTrue(laser.waitForScans(laser.getScanCount() + 1, PATIENCE_MS));
      assertEquals(2000, laser.currentReadingPolar(80, 100), 2.0);
      assertEquals(0, laser.getDropCounters().total(), "a clean line damages nothing");
      laser.disconnect();
      assertFalse(laser.isConnected());
    }
  }

  @Test
  void slowAnswersAndLostBytesCostRetriesNotTheConnection() throws Exception {
    DeviceFaults faults = DeviceFaults.NONE.withAnswerDelayMs(300).withDropEveryNthByte(500);
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device = new ArSerialConnection(pty.b.toString(), 9600, Clock.system());
        Lms200Emulator lms = Lms200Emulator.start(device, LaserSensor.of(robot), faults, 20);
        ArLMS2xx laser = new ArLMS2xx()) {
      laser.setDeviceConnection(new ArSerialConnection(pty.a.toString(), 9600, Clock.system()));
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      // At this loss rate about three telegrams are dropped before each good scan after the first
      // (a lost byte spoils its scan, and the reader may take a false start in the next one for a
      // telegram): four scans show the reader finding its way back three times.
      assertTrue(laser.waitForScans(4, PATIENCE_MS), "scans keep coming despite lost bytes");
      assertTrue(laser.getDropCounters().total() > 0, "the damaged scans were counted and dropped");
      assertEquals(181, laser.getLaserScan().size());
      assertTrue(lms.isRunning());
      assertEquals(3000 - laserPose().x(), at(laser.getLaserScan(), 0), 1.0);
    }
  }

  @Test
  void aLaserUnpluggedMidScanIsReportedNotWaitedFor() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device = new ArSerialConnection(pty.b.toString(), 9600, Clock.system());
        Lms200Emulator lms =
            Lms200Emulator.start(
                device, LaserSensor.of(robot), DeviceFaults.NONE.withUnplugAfterScans(3), 20);
        ArLMS2xx laser = new ArLMS2xx()) {
      laser.setConnectionTimeoutMs(1000);
      laser.setDeviceConnection(new ArSerialConnection(pty.a.toString(), 9600, Clock.system()));
      boolean[] told = new boolean[1];
      laser.addDisconnectOnErrorCB(() -> told[0] = true);
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertTrue(lms.join(PATIENCE_MS), "the emulator was unplugged");
      assertTrue(lms.wasUnplugged());
      assertTrue(laser.waitForDisconnect(PATIENCE_MS), "the driver noticed");
      assertEquals(3, laser.getScanCount(), "the half scan was not taken");
      assertTrue(told[0], "the disconnect-on-error callbacks ran");
      String why = laser.getConnectFailure();
      assertTrue(why.contains("lost"), why);
    }
  }

  @Test
  void reconnectsOverTcpAfterAnUnplug() throws Exception {
    try (DeviceTcpServer server =
            new DeviceTcpServer(
                0,
                (c, i) ->
                    new Lms200Emulator(
                        c,
                        LaserSensor.of(robot),
                        i == 0 ? DeviceFaults.NONE.withUnplugAfterScans(2) : DeviceFaults.NONE,
                        20));
        ArLMS2xx laser = new ArLMS2xx()) {
      laser.setConnectionTimeoutMs(1000);
      laser.setDeviceConnection(new ArTcpConnection("127.0.0.1", server.getPort()));
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertTrue(laser.waitForDisconnect(PATIENCE_MS), "lost after the unplug");
      assertEquals(2, laser.getScanCount());
      assertTrue(laser.blockingConnect(), "reconnects: " + laser.getConnectFailure());
      assertTrue(laser.waitForScans(5, PATIENCE_MS), "scans resume");
      assertNotNull(laser.getLaserScan());
      assertEquals(2, server.getDevices().size());
    }
  }

  /**
   * AriaCoda's ArLMS2xx asks for the variant with a resolution of 0 (it sends an increment field
   * that is never set: the bytes below are what its laserConnect sends for 180° at 1°). The
   * emulator keeps its resolution and says yes, so AriaCoda's laser programs connect.
   */
  @Test
  void ariaCodasVariantRequestWithResolutionZeroIsAccepted() throws Exception {
    byte[] ariaCoda = LmsTelegram.toLaser(0x3B, (byte) 0xB4, (byte) 0, (byte) 0, (byte) 0).encode();
    try (DeviceTcpServer server =
            new DeviceTcpServer(
                0, (c, i) -> new Lms200Emulator(c, LaserSensor.of(robot), DeviceFaults.NONE, 20));
        java.net.Socket socket =
            new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), server.getPort())) {
      socket.setSoTimeout((int) PATIENCE_MS);
      socket.getOutputStream().write(ariaCoda);
      java.io.DataInputStream in = new java.io.DataInputStream(socket.getInputStream());
      assertEquals(LmsTelegram.ACK, in.readUnsignedByte());
      assertEquals(LmsTelegram.STX, in.readUnsignedByte());
      assertEquals(LmsTelegram.FROM_LASER, in.readUnsignedByte());
      int len = in.readUnsignedByte() | in.readUnsignedByte() << 8;
      byte[] body = new byte[len];
      in.readFully(body);
      assertEquals(0xBB, body[0] & 0xFF, "the variant answer");
      assertEquals(1, body[1], "accepted (ARIA gives up on 0)");
      assertEquals(180, (body[2] & 0xFF) | (body[3] & 0xFF) << 8, "180°");
      assertEquals(100, (body[4] & 0xFF) | (body[5] & 0xFF) << 8, "at the 1° it had");
    }
  }

  /**
   * A slow LMS-200 takes 12 s to store its configuration (EEPROM) before answering: the driver
   * sends the block once and waits, as ARIA does (14 s), instead of giving up after three tries of
   * 2 s, each of which would have been another EEPROM write. Virtual time: no real waiting.
   */
  @Test
  void aSlowConfigurationIsAwaitedAsAriaDoesAndStoredOnce() throws Exception {
    VirtualClock clock = new VirtualClock();
    PipeConnection.Pair pipe = PipeConnection.pair(clock, "lms");
    try (Lms200Emulator lms =
            new Lms200Emulator(pipe.b(), LaserSensor.of(robot), DeviceFaults.NONE, 200);
        ArLMS2xx laser = new ArLMS2xx()) {
      lms.setConfigureDelayMs(12_000);
      lms.start();
      laser.setDeviceConnection(pipe.a());
      assertTrue(onVirtualTime(clock, laser::blockingConnect), laser.getConnectFailure());
      assertEquals(1, lms.getConfigurationsStored(), "one EEPROM write");
      assertTrue(clock.nanoTime() >= TimeUnit.SECONDS.toNanos(12), clock.toString());
      onVirtualTime(clock, () -> laser.waitForScans(2, PATIENCE_MS));
      assertEquals(181, laser.getLaserScan().size());
    }
  }

  /** One that takes longer than ARIA waits fails with a message, still after one write. */
  @Test
  void aConfigurationNeverAnsweredFailsAfterOneWrite() throws Exception {
    VirtualClock clock = new VirtualClock();
    PipeConnection.Pair pipe = PipeConnection.pair(clock, "lms");
    try (Lms200Emulator lms =
            new Lms200Emulator(pipe.b(), LaserSensor.of(robot), DeviceFaults.NONE, 200);
        ArLMS2xx laser = new ArLMS2xx()) {
      lms.setConfigureDelayMs(60_000);
      lms.start();
      laser.setDeviceConnection(pipe.a());
      assertFalse(onVirtualTime(clock, laser::blockingConnect));
      String why = laser.getConnectFailure();
      assertTrue(why.contains("no answer to the units and reflector bits request"), why);
      assertTrue(clock.nanoTime() < TimeUnit.SECONDS.toNanos(30), "gave up at 14 s: " + clock);
      // Only the laser, still storing, waits on the clock now: let it finish.
      onVirtualTime(clock, 1, () -> lms.join(PATIENCE_MS));
      assertEquals(1, lms.getConfigurationsStored(), "one EEPROM write");
    }
  }

  /**
   * Disconnecting stops the output and puts the laser back to its power-up 9600 baud, as ARIA does:
   * otherwise the next program (ARIA's with -laserAutoBaud among them) finds it at 38400.
   */
  @Test
  void disconnectingPutsTheLaserBackTo9600Baud() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device = new ArSerialConnection(pty.b.toString(), 9600, Clock.system());
        Lms200Emulator lms =
            Lms200Emulator.start(device, LaserSensor.of(robot), DeviceFaults.NONE, 20);
        ArLMS2xx laser = new ArLMS2xx()) {
      ArSerialConnection port = new ArSerialConnection(pty.a.toString(), 9600, Clock.system());
      laser.setDeviceConnection(port);
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertTrue(laser.waitForScans(2, PATIENCE_MS));
      assertEquals(38400, port.getBaud());
      laser.disconnect();
      List<Integer> modes = lms.getModeChanges();
      // 0x40 to 38400 when connecting, ..., then stop (0x25) and 9600 baud (0x42) when leaving.
      assertEquals(0x40, modes.get(0), modes::toString);
      assertEquals(List.of(0x25, 0x42), modes.subList(modes.size() - 2, modes.size()));
      assertEquals(9600, port.getBaud(), "the port followed the laser back");
    }
  }

  /**
   * A laser lost while a program waits for scans wakes the program at once: the wait ends when the
   * reader knows, not when the program's own timeout (here an hour) runs out.
   */
  @Test
  void aLostLaserWakesWhoeverWaitsForScans() throws Exception {
    try (DeviceTcpServer server =
            new DeviceTcpServer(
                0,
                (c, i) ->
                    new Lms200Emulator(
                        c, LaserSensor.of(robot), DeviceFaults.NONE.withUnplugAfterScans(50), 20));
        ArLMS2xx laser = new ArLMS2xx()) {
      laser.setDeviceConnection(new ArTcpConnection("127.0.0.1", server.getPort()));
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      // Started while scans still arrive (the unplug comes after 50 of them, 1 s away).
      CompletableFuture<Boolean> waiting =
          CompletableFuture.supplyAsync(
              () -> {
                try {
                  return laser.waitForScans(1_000_000, TimeUnit.HOURS.toMillis(1));
                } catch (InterruptedException e) {
                  Thread.currentThread().interrupt();
                  return true;
                }
              });
      assertFalse(waiting.get(PATIENCE_MS, TimeUnit.MILLISECONDS), "woken by the loss");
      assertFalse(laser.isConnected());
      assertTrue(laser.getConnectFailure().contains("lost"), laser.getConnectFailure());
    }
  }

  /**
   * Runs {@code task} on a thread of its own while this one moves the virtual clock on, 20 ms at a
   * time, whenever two threads (the driver's and the emulator's) are waiting on it.
   */
  private static <T> T onVirtualTime(VirtualClock clock, Callable<T> task) throws Exception {
    return onVirtualTime(clock, 2, task);
  }

  /** As above, moving the clock on whenever {@code waiters} threads wait on it. */
  private static <T> T onVirtualTime(VirtualClock clock, int waiters, Callable<T> task)
      throws Exception {
    CompletableFuture<T> result = new CompletableFuture<>();
    Thread t =
        new Thread(
            () -> {
              try {
                result.complete(task.call());
              } catch (Exception | AssertionError e) {
                result.completeExceptionally(e);
              }
              clock.wakeWatchers();
            },
            "virtual-time-task");
    t.start();
    while (!result.isDone()) {
      clock.awaitWaiters(waiters, Duration.ofMillis(PATIENCE_MS), result::isDone);
      clock.advanceMillis(20);
    }
    t.join();
    return result.get();
  }

  @Test
  void noLaserOnThePortFailsWithAClearMessage() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArLMS2xx laser = new ArLMS2xx()) {
      laser.setAnswerTimeoutMs(200);
      laser.setDeviceConnection(new ArSerialConnection(pty.a.toString(), 9600, Clock.system()));
      assertFalse(laser.blockingConnect());
      String why = laser.getConnectFailure();
      assertTrue(why.contains("no answer at 9600 or 38400 baud"), why);
    }
  }
}
