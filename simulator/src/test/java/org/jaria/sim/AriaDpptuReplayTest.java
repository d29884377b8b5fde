package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.HexFormat;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.SerAuxPacket;
import org.jaria.sim.serial.PtzHead;
import org.junit.jupiter.api.Test;

/**
 * The TTY2 packets AriaCoda's {@code cameraPTZExample -ptzType dpptu} sent to {@code ./jaria sim
 * --ptz-type dpptu} (recorded with socat): ARIA's ArDPPTU set-up, then pan −90, +90, 0 and tilt +90
 * (clamped by ARIA to 30°), −20, 0. ARIA never asks for the unit's answers through the robot (it
 * reads them only on a direct serial line), so its "real position" stays −1; the answers wait in
 * the AUX1 buffer, and here they are fetched and checked: the unit took every command.
 */
class AriaDpptuReplayTest {

  private static final String[] ARIA_TTY2 = {
    "fafb082a2b032040206d6b", // " @ "
    "fafb0a2a2b0520504d4c20cbb8", // " PML "
    "fafb0a2a2b0520544d4c20cfb8", // " TML "
    "fafb0a2a2b052050484f20ceb3", // " PHO "
    "fafb0a2a2b052050484f20ceb3", // " PHO "
    "fafb092a2b04205052207ebd", // " PR "
    "fafb0e2a2b092050502d31373531201921", // " PP-1751 "
    "fafb0d2a2b082050503137353120e923", // " PP1751 "
    "fafb0a2a2b052050503020afbb", // " PP0 "
    "fafb0c2a2b0720545035383420eef3", // " TP584 "
    "fafb0d2a2b082054502d33383920ec27", // " TP-389 "
    "fafb0a2a2b052054503020b3bb", // " TP0 "
  };

  @Test
  void ariasDpptuCommandsAreAllTakenAndMoveTheHead() {
    try (SimWorld w = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withPtzType("dpptu"));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      HexFormat hex = HexFormat.of();
      for (int i = 0; i < 7; i++) {
        c.sendRaw(hex.parseHex(ARIA_TTY2[i]));
      }
      w.advanceMillis(200);
      PtzHead.Pointing left = r.getPtzPointing();
      assertEquals(-90.05, left.panRightDeg(), 0.01, "PP-1751: 90° left");
      for (int i = 7; i < ARIA_TTY2.length; i++) {
        c.sendRaw(hex.parseHex(ARIA_TTY2[i]));
      }
      w.advanceMillis(200);
      assertEquals(0, r.getPtzPointing().panRightDeg(), 1e-9);
      assertEquals(0, r.getPtzPointing().tiltUpDeg(), 1e-9);

      String done = "*\r\n";
      String resolution = "* 185.1428 seconds arc per position\r\n";
      String want = done.repeat(5) + resolution + done.repeat(6);
      c.clear();
      c.comInt(ArCommands.GETAUX, want.length());
      SerAuxPacket aux = SerAuxPacket.decode(c.awaitId(PacketIds.SERAUX1));
      assertEquals(want, new String(aux.data(), StandardCharsets.US_ASCII));
    }
  }
}
