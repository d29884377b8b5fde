package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.DropReason;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/** ArRobot against a scripted robot over an in-memory pipe, on virtual time. */
class ArRobotSessionTest {

  private final LockstepRig rig = new LockstepRig();

  @Test
  void handshakeSendsTheExactBytesOfTheSpec() {
    assertTrue(rig.connect(), rig.robot.getConnectFailure());
    List<FakeRobot.Received> r = rig.fake.received();
    assertEquals("FA FB 03 00 00 00", r.get(0).hex());
    assertEquals("FA FB 03 01 00 01", r.get(1).hex());
    assertEquals("FA FB 03 02 00 02", r.get(2).hex());
    assertEquals("FA FB 06 01 3B 01 00 02 3B", r.get(3).hex(), "OPEN with int 1");
    assertEquals("FA FB 06 12 3B 01 00 13 3B", r.get(4).hex(), "CONFIG with int 1");
    assertEquals("fake", rig.robot.getRobotName());
    assertEquals("Pioneer", rig.robot.getRobotType());
    assertEquals("p3dx-sh", rig.robot.getRobotSubType());
    assertEquals(16, rig.robot.getNumSonar());
    assertEquals(1500, rig.robot.getAbsoluteMaxTransVel());
    assertEquals(750, rig.robot.getTransVelMax());
    assertEquals("FAKE", rig.robot.getOrigRobotConfig().getSerialNumber());
  }

  @Test
  void subtypeIsLowerCasedAndUnknownSubtypeStillConnects() {
    rig.fake.identity("x", "Pioneer", "P3DX-SH");
    assertTrue(rig.connect());
    assertEquals("p3dx-sh", rig.robot.getRobotSubType());

    LockstepRig other = new LockstepRig();
    other.fake.identity("y", "Weird", "no-such-robot");
    assertTrue(other.connect());
    assertEquals("no-such-robot", other.robot.getRobotSubType());
  }

  @Test
  void enableAndVelocityAreSentAsTheSpecSays() {
    assertTrue(rig.connect());
    rig.run(300);
    rig.fake.clearReceived();
    assertTrue(rig.robot.enableMotors());
    rig.robot.setVel(-200);
    rig.run(150);
    List<FakeRobot.Received> r = rig.fake.received();
    assertEquals("FA FB 06 04 3B 01 00 05 3B", r.get(0).hex());
    assertEquals(1, rig.fake.received(ArCommands.VEL).size());
    assertEquals("FA FB 06 0B 1B C8 00 D3 1B", rig.fake.received(ArCommands.VEL).get(0).hex());
  }

  @Test
  void unchangedVelocityIsRefreshedEvery500msAndChangesGoOutAtOnce() {
    assertTrue(rig.connect());
    rig.robot.setVel(300);
    rig.run(50);
    rig.fake.clearReceived();
    rig.run(2000);
    List<FakeRobot.Received> vels = rig.fake.received(ArCommands.VEL);
    assertTrue(vels.size() >= 3 && vels.size() <= 4, "refreshes: " + vels.size());
    for (int i = 1; i < vels.size(); i++) {
      long gap = (vels.get(i).timeNanos() - vels.get(i - 1).timeNanos()) / 1_000_000;
      assertTrue(gap >= 500 && gap <= 600, "gap " + gap);
    }
    rig.fake.clearReceived();
    rig.robot.setVel(100);
    rig.run(100);
    assertEquals(100, rig.fake.received(ArCommands.VEL).get(0).intArg());
  }

  @Test
  void idleRobotGetsPulsesOftenEnoughForTheWatchdog() {
    assertTrue(rig.connect());
    rig.run(1000);
    rig.fake.clearReceived();
    rig.run(5000);
    List<FakeRobot.Received> all = rig.fake.received();
    assertFalse(all.isEmpty());
    assertTrue(rig.fake.received(ArCommands.PULSE).size() >= 7);
    long last = rig.clock.nanoTime() - 5_000_000_000L;
    for (FakeRobot.Received x : all) {
      assertTrue((x.timeNanos() - last) / 1_000_000 <= 700, "silence before " + x);
      last = x.timeNanos();
    }
  }

  @Test
  void robotLeftOpenByAnEarlierClientIsClosedThenConnected() {
    rig.fake.alreadyOpen();
    assertTrue(rig.connect(), rig.robot.getConnectFailure());
    assertTrue(rig.fake.received(ArCommands.CLOSE).size() >= 1);
    assertTrue(rig.fake.isOpen());
  }

  @Test
  void deadRobotFailsWithAClearMessageAndCallsBack() {
    rig.fake.answerSync(false);
    AtomicInteger failed = new AtomicInteger();
    rig.robot.addFailedConnectCB(failed::incrementAndGet);
    assertFalse(rig.connect());
    assertEquals(1, failed.get());
    assertTrue(rig.robot.getConnectFailure().contains("no robot is responding"));
    long seconds = rig.clock.nanoTime() / 1_000_000_000L;
    assertTrue(seconds >= 5 && seconds <= 15, "gave up after " + seconds + " s");
  }

  @Test
  void configThatNeverComesStillConnectsWithParameterLimits() {
    rig.fake.answerConfig(false);
    assertTrue(rig.connect());
    assertEquals(null, rig.robot.getOrigRobotConfig());
    assertEquals(2200, rig.robot.getAbsoluteMaxTransVel());
  }

  @Test
  void silenceForEightSecondsIsALostConnection() {
    assertTrue(rig.connect());
    AtomicInteger lost = new AtomicInteger();
    rig.robot.addDisconnectOnErrorCB(lost::incrementAndGet);
    rig.run(1000);
    rig.sendSips = false;
    rig.run(7500);
    assertTrue(rig.robot.isConnected());
    rig.run(1000);
    assertFalse(rig.robot.isConnected());
    assertEquals(1, lost.get());
  }

  @Test
  void garbageBetweenSipsIsCountedAndStateStillFlows() throws Exception {
    assertTrue(rig.connect());
    rig.sip.setPos(100, 0, 0);
    rig.run(200);
    rig.fake.sendRaw(new byte[] {(byte) 0xFA, (byte) 0xFB, 9, 0x32, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    rig.sip.setPos(300, 0, 0);
    rig.run(200);
    assertEquals(300, rig.robot.getX(), 1e-9);
    assertTrue(rig.robot.getDropCounters().get(DropReason.BAD_CHECKSUM) >= 1);
  }

  @Test
  void closeSendsCloseAndTellsTheCallbacks() {
    assertTrue(rig.connect());
    AtomicInteger normal = new AtomicInteger();
    rig.robot.addDisconnectNormallyCB(normal::incrementAndGet);
    rig.robot.close();
    rig.run(50);
    assertFalse(rig.robot.isConnected());
    assertEquals(1, normal.get());
    assertFalse(rig.fake.isOpen());
    List<FakeRobot.Received> closes = rig.fake.received(ArCommands.CLOSE); // SYNC2 shares ID 2
    assertEquals("FA FB 06 02 3B 01 00 03 3B", closes.get(closes.size() - 1).hex());
  }
}
