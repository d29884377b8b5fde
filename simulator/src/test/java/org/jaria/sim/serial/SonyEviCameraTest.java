package org.jaria.sim.serial;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.util.HexFormat;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/** The VISCA camera's answers, byte for byte. */
class SonyEviCameraTest {

  private final SonyEviCamera cam = new SonyEviCamera();

  private String send(String hex) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    cam.receive(HexFormat.ofDelimiter(" ").parseHex(hex.toLowerCase(Locale.ROOT)), out::writeBytes);
    return HexFormat.ofDelimiter(" ").withUpperCase().formatHex(out.toByteArray());
  }

  @Test
  void broadcastsComeBackAsTheChainReturnsThem() {
    assertEquals("88 01 00 01 FF 88 30 02 FF", send("88 01 00 01 FF 88 30 01 FF"));
    assertEquals(1, cam.getAddress());
  }

  @Test
  void commandsAreAcknowledgedThenCompleted() {
    // pan +100°, tilt −25°
    assertEquals("90 41 FF 90 51 FF", send("81 01 06 02 18 14 00 03 07 00 0F 0E 0D 04 FF"));
    assertEquals(100, cam.getPan(), 1e-9);
    assertEquals(-25, cam.getTilt(), 1e-9);
    assertEquals("90 50 00 03 07 00 0F 0E 0D 04 FF", send("81 09 06 12 FF"));
    assertEquals("90 41 FF 90 51 FF", send("81 01 04 47 00 03 0F 0F FF"));
    assertEquals("90 50 00 03 0F 0F FF", send("81 09 04 47 FF"));
    assertEquals(1.0, cam.pointing().zoomFraction(), 1e-9);
    // relative: 10 units left from +0x370
    assertEquals("90 41 FF 90 51 FF", send("81 01 06 03 18 14 0F 0F 0F 06 00 00 00 00 FF"));
    assertEquals(0x370 - 10, cam.getPanUnits());
    assertEquals("90 41 FF 90 51 FF", send("81 01 04 33 02 FF"));
    assertEquals("90 50 02 FF", send("81 09 04 33 FF"));
  }

  @Test
  void outOfRangeGarbageAndNoiseAreRefusedOrSkipped() {
    assertEquals("90 61 41 FF", send("81 01 06 02 18 14 00 03 07 01 00 00 00 00 FF"));
    assertEquals(0, cam.getPanUnits(), "a refused position does not move the head");
    assertEquals("90 60 02 FF", send("81 01 06 02 18 14 10 00 00 00 00 00 00 00 FF"));
    assertEquals("90 60 02 FF", send("81 01 7E 01 FF"));
    assertEquals("90 60 02 FF", send("81 09 06 12 00 FF"));
    assertEquals("", send("00 11 22"));
    assertEquals(3, cam.skippedBytes());
    assertEquals("90 60 03 FF", send("81 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00"));
    assertEquals("90 50 00 00 00 00 00 00 00 00 FF", send("81 09 06 12 FF"), "still answers");
  }

  @Test
  void chunksMayArriveSplitAnywhere() {
    assertEquals("", send("81 01 06 02 18"));
    assertEquals("90 41 FF 90 51 FF", send("14 00 00 01 00 00 00 00 0C FF"));
    assertEquals(16 / SonyEviCamera.PAN_UNITS_PER_DEG, cam.getPan(), 1e-9);
    assertEquals(12 / SonyEviCamera.TILT_UNITS_PER_DEG, cam.getTilt(), 1e-9);
  }
}
