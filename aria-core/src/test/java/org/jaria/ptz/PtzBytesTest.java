package org.jaria.ptz;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.HexFormat;
import org.jaria.clock.Clock;
import org.jaria.connection.PipeConnection;
import org.junit.jupiter.api.Test;

/** The bytes the Sony and Directed Perception units receive, checked against byte vectors. */
class PtzBytesTest {

  private static byte[] hex(String s) {
    return HexFormat.ofDelimiter(" ").parseHex(s.toLowerCase(java.util.Locale.ROOT));
  }

  /** Everything that has arrived at the unit's end of the pipe. */
  private static byte[] drain(PipeConnection unit) throws Exception {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    byte[] buf = new byte[256];
    int n;
    while ((n = unit.read(buf, 0, buf.length, 0)) > 0) {
      out.write(buf, 0, n);
    }
    return out.toByteArray();
  }

  @Test
  void viscaCommandsAreTheDocumentedBytes() {
    assertArrayEquals(hex("88 01 00 01 FF 88 30 01 FF"), Visca.init());
    assertArrayEquals(
        hex("81 01 06 02 18 14 00 03 07 00 00 01 02 0C FF"), Visca.panTilt(0x370, 0x12c));
    assertArrayEquals(
        hex("81 01 06 02 18 14 0F 0C 09 00 0F 0E 0D 04 FF"), Visca.panTilt(-0x370, -0x12c));
    assertArrayEquals(hex("81 01 04 47 00 03 0F 0F FF"), Visca.zoom(1023));
  }

  @Test
  void theSonyCameraClampsAndSendsVisca() throws Exception {
    PipeConnection.Pair pipe = PipeConnection.pair(Clock.system());
    pipe.a().open();
    pipe.b().open();
    ArSonyPTZ sony = new ArSonyPTZ(null);
    sony.setDeviceConnection(pipe.a());
    sony.panTilt(200, -25);
    assertEquals(95, sony.getPan(), "clamped to the unit's limit");
    assertEquals(-25, sony.getTilt());
    // 95° is 836 = 0x344 pan units (0x370 is 100°); −25° is −300 = 0xFED4
    assertArrayEquals(hex("81 01 06 02 18 14 00 03 04 04 0F 0E 0D 04 FF"), drain(pipe.b()));
    sony.zoom(5000);
    assertEquals(1023, sony.getZoom());
    assertArrayEquals(Visca.zoom(1023), drain(pipe.b()));
  }

  @Test
  void thePtuGetsAsciiPositions() throws Exception {
    PipeConnection.Pair pipe = PipeConnection.pair(Clock.system());
    pipe.a().open();
    pipe.b().open();
    ArDPPTU ptu = new ArDPPTU(null);
    ptu.setDeviceConnection(pipe.a());
    ptu.init();
    ptu.panTilt(10, -5);
    ptu.panSlew(30);
    ArDPPTU ptu70 = new ArDPPTU(null, ArDPPTU.Model.PANTILT_PTU46_70);
    ptu70.setDeviceConnection(pipe.a());
    ptu70.tilt(10);
    assertEquals(
        "I PP0 TP0 PP195 TP-97 PS584 PP0 TP775 ",
        new String(drain(pipe.b()), StandardCharsets.US_ASCII));
  }
}
