package org.jaria.sim.serial;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The Directed Perception unit's answers, character for character. */
class DpPtuTest {

  private final DpPtu ptu = new DpPtu();

  private String send(String text) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ptu.receive(text.getBytes(StandardCharsets.US_ASCII), out::writeBytes);
    return out.toString(StandardCharsets.US_ASCII);
  }

  @Test
  void commandsQueriesAndLimits() {
    assertEquals("*\r\n*\r\n", send("I PP195 "));
    assertEquals("* Current Pan position is 195\r\n", send("PP "));
    assertEquals("*\r\n* Current Tilt position is -97\r\n", send("tp-97\rTP\n"));
    assertEquals(195 * DpPtu.DEG_PER_STEP, ptu.getPan(), 1e-9);
    assertEquals("* 185.1428 seconds arc per position\r\n", send("PR "));
    assertEquals("* Maximum Pan position is 3090\r\n", send("PX "));
    assertEquals("! Maximum allowable Pan position exceeded\r\n", send("PP3091 "));
    assertEquals("! Minimum allowable Tilt position exceeded\r\n", send("TP-908 "));
    assertEquals(195, ptu.getPanSteps(), "refused positions leave the head where it was");
    assertEquals("*\r\n* Current Pan position is 205\r\n", send("PO10 PP "));
    assertEquals("*\r\n* 205\r\n", send("FT PP "), "terse feedback");
  }

  @Test
  void ariasSetUpSequenceIsAccepted() {
    // what ARIA's ArDPPTU::init sends: init, move power low, hold power off, resolution query
    assertEquals(
        "*\r\n*\r\n*\r\n*\r\n*\r\n* 185.1428 seconds arc per position\r\n",
        send(" @  PML  TML  PHO  PHO  PR "));
    assertEquals("*\r\n", send(" ps100 "), "lower-case speed as ARIA sends it");
    assertEquals(100, ptu.getPanSpeed());
  }

  @Test
  void garbageGetsAnErrorNotAHang() {
    assertEquals("! Illegal command\r\n", send("XYZ "));
    assertEquals("! Illegal argument\r\n", send("PP12a "));
    String flood = "Q".repeat(10_000) + " ";
    assertEquals("! Illegal command\r\n", send(flood), "a long word is cut, answered once");
    assertEquals(3, ptu.errors());
  }
}
