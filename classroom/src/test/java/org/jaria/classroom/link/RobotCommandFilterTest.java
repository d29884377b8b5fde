package org.jaria.classroom.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Map;
import org.jaria.clock.VirtualClock;
import org.jaria.connection.PipeConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.junit.jupiter.api.Test;

/**
 * What the grading world takes from a student's robot link: the ARCOS commands of a real Pioneer,
 * however the bytes are cut, and nothing else; every drop counted.
 */
class RobotCommandFilterTest {

  @Test
  void aRealPioneersCommandsPassAndNoSimulatorCommandDoes() {
    for (ArCommands c : ArCommands.values()) {
      assertEquals(!c.name().startsWith("SIM_"), RobotCommands.accepted(c.getNumber()), c.name());
    }
    assertTrue(RobotCommands.accepted(0)); // SYNC0, the handshake
    assertFalse(RobotCommands.accepted(ArCommands.SIM_SET_POSE.getNumber()));
    assertFalse(RobotCommands.accepted(ArCommands.SIM_EXIT.getNumber()));
    assertFalse(RobotCommands.accepted(200)); // no ARCOS command
    assertEquals("SIM_CTRL", RobotCommands.name(236));
    assertEquals("command 200", RobotCommands.name(200));
  }

  private static byte[] packet(ArRobotPacket p) {
    return p.toByteArray();
  }

  @Test
  void onlyTheAcceptedPacketsReachTheRobotAndTheRestIsCounted() throws IOException {
    VirtualClock clock = new VirtualClock();
    PipeConnection.Pair pipe = PipeConnection.pair(clock, "robot");
    pipe.a().open();
    pipe.b().open();
    LinkAudit audit = new LinkAudit();
    RobotCommandFilter f = new RobotCommandFilter(audit, "test");
    byte[] move =
        packet(CommandCodec.comInt(new ArRobotPacket(), ArCommands.MOVE.getNumber(), 500));
    ArRobotPacket pose = new ArRobotPacket(ArCommands.SIM_SET_POSE.getNumber());
    pose.uByteToBuf(0).byte4ToBuf(2000).byte4ToBuf(0).byte4ToBuf(0);
    byte[] teleport = packet(pose.finalizePacket());
    byte[] damaged = move.clone();
    damaged[damaged.length - 1] ^= 0x55;
    ByteArrayOutputStream all = new ByteArrayOutputStream();
    all.write(teleport);
    all.write("garbage".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
    all.write(damaged);
    all.write(move);
    byte[] b = all.toByteArray();
    // cut in two, in the middle of the last packet: it is held until the rest arrives
    int cut = b.length - 3;
    f.feed(b, cut, 0, pipe.a());
    byte[] head = new byte[3];
    System.arraycopy(b, cut, head, 0, 3);
    f.feed(head, 3, 1_000_000, pipe.a());
    byte[] got = new byte[256];
    int n = pipe.b().read(got, 0, got.length, 0);
    byte[] received = java.util.Arrays.copyOf(got, Math.max(0, n));
    assertArrayEquals(move, received, "only the good MOVE reaches the robot");
    assertEquals(Map.of("SIM_SET_POSE", 1L, "damaged packets", 1L), audit.dropped());
    assertTrue(audit.garbageBytes() >= "garbage".length(), String.valueOf(audit.garbageBytes()));
    assertFalse(audit.clean());
  }
}
