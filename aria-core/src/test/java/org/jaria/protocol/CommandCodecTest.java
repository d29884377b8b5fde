package org.jaria.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

class CommandCodecTest {

  private final ArRobotPacket p = new ArRobotPacket();

  @Test
  void integerArgumentsRoundTripWithTheirSign() {
    for (int v : new int[] {0, 1, -1, 200, -200, 32767, -32768, 65535, -65535}) {
      CommandCodec.comInt(p, 11, v);
      assertEquals(v, CommandCodec.readIntArg(p, Integer.MIN_VALUE), "value " + v);
      assertEquals(v < 0 ? ArgKind.NEG_INT_ARG : ArgKind.INT_ARG, p.getBuf()[4] & 0xFF);
    }
  }

  @Test
  void integerOutOfRangeIsRefused() {
    assertThrows(IllegalArgumentException.class, () -> CommandCodec.comInt(p, 11, 70000));
    assertThrows(IllegalArgumentException.class, () -> CommandCodec.comInt(p, 11, -70000));
  }

  @Test
  void missingArgumentGivesTheFallback() {
    CommandCodec.com(p, 29);
    assertEquals(-99, CommandCodec.readIntArg(p, -99));
  }

  @Test
  void twoBytesPackHighThenLow() {
    CommandCodec.com2Bytes(p, 32, -10, 10);
    assertEquals("FA FB 06 20 3B 0A F6 2B 31", p.toHexString());
    int v = CommandCodec.readIntArg(p, 0);
    assertEquals(-10, (byte) (v >> 8));
    assertEquals(10, (byte) v);
  }

  @Test
  void stringsCarryLengthCharactersAndNul() {
    CommandCodec.comStr(p, 3, "\u0001\u0002\u0003");
    assertEquals("FA FB 09 03 2B 03 01 02 03 00", p.toHexString().substring(0, 29));
    assertArrayEquals(new byte[] {1, 2, 3}, CommandCodec.readDataArg(p));
    CommandCodec.comStr(p, 59, "hi");
    assertEquals("hi", CommandCodec.readStringArg(p));
  }

  @Test
  void rawDataCommandsKeepEveryByte() {
    byte[] say = {10, 60, 0, 0, 20, 64};
    CommandCodec.comDataN(p, 15, say, 0, say.length);
    assertArrayEquals(say, CommandCodec.readDataArg(p));
  }

  @Test
  void everyCommandHasAUniqueNumberAndIsFoundByIt() {
    Set<Integer> seen = new HashSet<>();
    for (ArCommands c : ArCommands.values()) {
      assertEquals(c, ArCommands.fromNumber(c.getNumber()));
      assertEquals(true, seen.add(c.getNumber()), "duplicate " + c);
    }
    assertEquals(ArCommands.JOYREQUEST, ArCommands.JOYINFO);
    assertEquals(null, ArCommands.fromNumber(200));
    assertEquals(224, ArCommands.SIM_SET_POSE.getNumber());
    assertEquals(ArgKind.TWO_BYTES, ArCommands.VEL2.getArgKind());
    assertEquals(ArgKind.STRING, ArCommands.POLLING.getArgKind());
    assertEquals(ArgKind.NONE, ArCommands.E_STOP.getArgKind());
    assertEquals(ArgKind.UINT, ArCommands.SONARCYCLE.getArgKind());
  }
}
