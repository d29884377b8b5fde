package org.jaria.ptz;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.Hex;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/** A VC-C4 driven through the robot: its packets travel as TTY2 commands to the AUX port. */
class ArVCC4OverRobotTest {

  @Test
  void panTiltBytesGoOutThroughTty2Unchanged() {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    ArVCC4 camera = new ArVCC4(bytes -> rig.robot.comDataN(ArCommands.TTY2, bytes));
    rig.fake.clearReceived();
    camera.panTilt(30, -10);
    rig.run(50);
    List<FakeRobot.Received> tty2 = rig.fake.received(ArCommands.TTY2);
    assertEquals(1, tty2.size());
    byte[] sent = Hex.parse(tty2.get(0).hex());
    byte[] want = VCC4Packets.panTilt(30, -10);
    // FA FB count 42 2B len <camera bytes> checksum
    assertEquals(want.length, sent[5] & 0xFF);
    byte[] payload = java.util.Arrays.copyOfRange(sent, 6, 6 + want.length);
    assertArrayEquals(want, payload);
    assertEquals(30, camera.getPan(), 1e-9);
  }

  @Test
  void onTheRobotFramesArePacedAndANewerPositionReplacesAQueuedOne() {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    ArVCC4 camera = new ArVCC4(rig.robot);
    rig.fake.clearReceived();
    // Like Chase: a tilt nudge every 100 ms cycle for two seconds.
    for (int i = 0; i < 20; i++) {
      camera.tiltRel(1);
      rig.run(100);
    }
    rig.run(1000); // let the queue drain
    List<FakeRobot.Received> tty2 = rig.fake.received(ArCommands.TTY2);
    // 3 s at one frame per 300 ms is at most 10 frames (plus the first, sent at once).
    assertTrue(tty2.size() <= 11, "paced: " + tty2.size() + " frames in 3 s");
    assertTrue(tty2.size() >= 5, "but kept sending: " + tty2.size());
    byte[] last = Hex.parse(tty2.get(tty2.size() - 1).hex());
    byte[] want = VCC4Packets.panTilt(0, 20);
    byte[] payload = java.util.Arrays.copyOfRange(last, 6, 6 + want.length);
    assertArrayEquals(want, payload, "the last frame sent is the latest target, tilt 20");
  }

  @Test
  void thePacedSinkSpacesFramesOnItsClock() {
    org.jaria.clock.VirtualClock clock = new org.jaria.clock.VirtualClock();
    java.util.List<byte[]> out = new java.util.ArrayList<>();
    PacedFrameSink sink = new PacedFrameSink(out::add, clock, 300);
    sink.accept(VCC4Packets.power(true));
    sink.accept(VCC4Packets.hostControlMode());
    sink.accept(VCC4Packets.panTilt(10, 0));
    sink.accept(VCC4Packets.panTilt(20, 0));
    assertEquals(1, out.size(), "only the first goes at once");
    assertEquals(2, sink.pending(), "host mode, then the newest pan/tilt");
    assertEquals(1, sink.supersededCount());
    clock.advance(java.time.Duration.ofMillis(299));
    sink.flush();
    assertEquals(1, out.size());
    clock.advance(java.time.Duration.ofMillis(1));
    sink.flush();
    assertArrayEquals(VCC4Packets.hostControlMode(), out.get(1));
    clock.advance(java.time.Duration.ofMillis(300));
    sink.flush();
    assertArrayEquals(VCC4Packets.panTilt(20, 0), out.get(2));
    assertEquals(0, sink.pending());
  }
}
