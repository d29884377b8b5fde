package org.jaria.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Terminal characters to key codes. */
class KeySequenceDecoderTest {

  private final List<Integer> keys = new ArrayList<>();
  private final KeySequenceDecoder d = new KeySequenceDecoder(keys::add);

  private List<Integer> decode(String s) {
    keys.clear();
    d.accept(s);
    return List.copyOf(keys);
  }

  @Test
  void plainKeys() {
    assertEquals(List.of((int) 'a', (int) '1', (int) 'Q'), decode("a1Q"));
    assertEquals(
        List.of(
            ArKeyHandler.SPACE,
            ArKeyHandler.TAB,
            ArKeyHandler.ENTER,
            ArKeyHandler.ENTER,
            ArKeyHandler.BACKSPACE,
            ArKeyHandler.BACKSPACE),
        decode(" \t\r\n\u007f\b"));
  }

  @Test
  void arrowKeysInBothCursorModes() {
    assertEquals(
        List.of(ArKeyHandler.UP, ArKeyHandler.DOWN, ArKeyHandler.RIGHT, ArKeyHandler.LEFT),
        decode("\033[A\033[B\033[C\033[D"));
    assertEquals(List.of(ArKeyHandler.UP, ArKeyHandler.LEFT), decode("\033OA\033OD"));
    assertEquals(List.of(ArKeyHandler.UP), decode("\033[1;5A"), "modifiers are ignored");
  }

  @Test
  void functionAndEditingKeys() {
    assertEquals(List.of(ArKeyHandler.F1, ArKeyHandler.F4), decode("\033OP\033OS"));
    assertEquals(
        List.of(ArKeyHandler.F5, ArKeyHandler.F8, ArKeyHandler.F12),
        decode("\033[15~\033[19~\033[24~"));
    assertEquals(
        List.of(
            ArKeyHandler.PAGEUP,
            ArKeyHandler.PAGEDOWN,
            ArKeyHandler.DEL,
            ArKeyHandler.INSERT,
            ArKeyHandler.HOME,
            ArKeyHandler.END),
        decode("\033[5~\033[6~\033[3~\033[2~\033[H\033[F"));
  }

  @Test
  void aLoneEscapeIsKnownOnlyAfterAPause() {
    assertEquals(List.of(), decode("\033"));
    assertTrue(d.isPending());
    d.timeout();
    assertEquals(List.of(ArKeyHandler.ESCAPE), keys);
    assertFalse(d.isPending());
    assertEquals(List.of(ArKeyHandler.ESCAPE), decode("\033\033"));
    d.timeout();
    assertEquals(List.of(ArKeyHandler.ESCAPE, ArKeyHandler.ESCAPE), keys);
    assertEquals(List.of(ArKeyHandler.ESCAPE, (int) 'x'), decode("\033x"));
  }

  @Test
  void garbageIsDroppedAndDecodingCarriesOn() {
    assertEquals(List.of((int) 'a'), decode("\033[99~a"));
    assertEquals(1, d.getDroppedSequences());
    assertEquals(List.of((int) 'b'), decode("\033[12345678901234567890Zb"));
    assertEquals(List.of(ArKeyHandler.UP), decode("\033[1\033[A"), "a new sequence interrupts");
    assertEquals(List.of(), decode("\033[1"));
    d.timeout();
    assertEquals(List.of(), keys, "a cut-short sequence is no key");
    assertTrue(d.getDroppedSequences() >= 4);
  }

  @Test
  void randomInputNeverBreaksTheDecoder() {
    Random rnd = new Random(7);
    for (int i = 0; i < 100_000; i++) {
      int c = rnd.nextInt(10) == 0 ? 27 : rnd.nextInt(10) == 0 ? '[' : rnd.nextInt(200);
      d.accept(c);
      if (rnd.nextInt(50) == 0) {
        d.timeout();
      }
    }
    d.timeout();
    assertFalse(d.isPending());
    for (int k : keys) {
      assertTrue(k > 0 && k <= ArKeyHandler.DEL, "key " + k);
    }
  }
}
