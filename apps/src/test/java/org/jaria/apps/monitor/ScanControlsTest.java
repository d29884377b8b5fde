package org.jaria.apps.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.net.ArNetPacket;
import org.junit.jupiter.api.Test;

/** What the mapping services' replies mean to the monitor, as values. */
class ScanControlsTest {

  private static ArNetPacket reply(byte... body) {
    ArNetPacket p = new ArNetPacket(300);
    for (byte b : body) {
      p.byteToBuf(b);
    }
    return p.toReader();
  }

  @Test
  void startReplies() {
    assertTrue(ScanControls.startReply(reply((byte) 0)).ok());
    assertEquals(
        "A scan is running already: end it first", ScanControls.startReply(reply((byte) 1)).text());
    ArNetPacket refused = new ArNetPacket(300);
    refused.byteToBuf(2).strToBuf("a scan's file name does not start with a dot");
    ScanControls.Reply r = ScanControls.startReply(refused.toReader());
    assertFalse(r.ok());
    assertEquals(
        "The server could not start the scan: a scan's file name does not start with a dot",
        r.text());
    assertEquals(
        "The server could not start the scan (its log says why)",
        ScanControls.startReply(reply((byte) 2)).text(),
        "ARIA's server gives no reason");
    assertFalse(ScanControls.startReply(reply()).ok(), "an empty answer");
  }

  @Test
  void endReplies() {
    assertTrue(ScanControls.endReply(reply((byte) 0, (byte) 0)).ok(), "ArNetworking's ubyte2 0");
    assertEquals("No scan is running", ScanControls.endReply(reply((byte) 1)).text());
    assertFalse(ScanControls.endReply(reply((byte) 2, (byte) 0)).ok());
    assertFalse(ScanControls.endReply(reply()).ok(), "an empty answer");
  }
}
