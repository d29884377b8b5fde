package org.jaria.ptz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.charset.StandardCharsets;
import java.util.HexFormat;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/** The units' answers as the drivers parse them, cut anywhere, with garbage among them. */
class PtzRepliesTest {

  private static byte[] hex(String s) {
    return HexFormat.ofDelimiter(" ").parseHex(s.toLowerCase(Locale.ROOT));
  }

  @Test
  void viscaAnswersInAnyChunks() {
    ArSonyPTZ sony = new ArSonyPTZ(null);
    byte[] all =
        hex(
            "90 41 FF 90 51 FF"
                + " 90 50 00 03 07 00 0F 0E 0D 04 FF" // pan 0x370, tilt −300
                + " 90 50 00 03 0F 0F FF" // zoom 1023
                + " 90 60 02 FF"); // syntax error
    for (int i = 0; i < all.length; i += 4) {
      byte[] chunk = java.util.Arrays.copyOfRange(all, i, Math.min(all.length, i + 4));
      sony.replyBytes(chunk);
    }
    assertEquals(1, sony.getAckCount());
    assertEquals(1, sony.getCompletionCount());
    assertEquals(100, sony.getReportedPan(), 1e-9);
    assertEquals(-25, sony.getReportedTilt(), 1e-9);
    assertEquals(1023, sony.getReportedZoom());
    assertEquals(1, sony.getErrorCount());
    assertEquals(2, sony.getLastError().errorCode());
  }

  @Test
  void aViscaFloodWithoutTerminatorsIsDroppedAndParsingResumes() {
    ArSonyPTZ sony = new ArSonyPTZ(null);
    byte[] flood = new byte[10_000];
    java.util.Arrays.fill(flood, (byte) 0x42);
    sony.replyBytes(flood);
    sony.replyBytes(hex("FF 90 41 FF"));
    assertEquals(1, sony.getAckCount());
    assertFalse(sony.canGetRealPanTilt());
  }

  @Test
  void ptuLinesWithErrorsAndGarbledNumbers() {
    ArDPPTU ptu = new ArDPPTU(null);
    String s =
        String.join(
                "\r\n",
                "*",
                "* Current Pan position is 195",
                "! Illegal command",
                "* Current Tilt position is x",
                "* Current Tilt position is -97")
            + "\r\n";
    byte[] b = s.getBytes(StandardCharsets.US_ASCII);
    for (int i = 0; i < b.length; i += 7) {
      ptu.replyBytes(java.util.Arrays.copyOfRange(b, i, Math.min(b.length, i + 7)));
    }
    assertEquals(1, ptu.getDoneCount());
    assertEquals(195 * 0.0514, ptu.getReportedPan(), 1e-9);
    assertEquals(-97 * 0.0514, ptu.getReportedTilt(), 1e-9);
    assertEquals(2, ptu.getErrorCount(), "the error line and the garbled number");
    assertEquals("* Current Tilt position is x", ptu.getLastError());
  }
}
