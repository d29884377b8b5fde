package org.jaria.acts.ptz;

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
}
