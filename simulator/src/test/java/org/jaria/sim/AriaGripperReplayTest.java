package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.junit.jupiter.api.Test;

/**
 * The gripper commands AriaCoda's {@code gripperExample} sent to {@code ./jaria sim} (recorded with
 * socat while the keys o, d, c, u were pressed), replayed against a default P3-DX, with the answers
 * read the way ARIA's {@code ArGripper} reads them (written out here from ARIA's source, so the
 * check does not depend on JAria's decoder). The run printed, in order: closed, between, open; lift
 * maxed, between, maxed; and back.
 */
class AriaGripperReplayTest {

  private static final HexFormat HEX = HexFormat.of();

  /** GRIPPERPACREQUEST 2, sent by ArGripper's connect callback. */
  private static final String REQUEST = "fafb06253b0200273b";

  /** GRIPPERPACREQUEST 0, sent after the first GRIPPERpac. */
  private static final String STOP = "fafb06253b0000253b";

  private static final String OPEN = "fafb06213b0100223b";
  private static final String LIFT_DOWN = "fafb06213b0500263b";
  private static final String CLOSE = "fafb06213b0200233b";
  private static final String LIFT_UP = "fafb06213b0400253b";

  /** ARIA's ArGripper::getGripState for a user-I/O gripper (d = DIGIN). */
  private static String ariaGrip(int d) {
    if ((d & 0x10) == 0 && (d & 0x20) == 0) {
      return "closed";
    }
    return (d & 0x01) == 0 ? "open" : "between";
  }

  /** ARIA's ArGripper::isLiftMaxed for a user-I/O gripper. */
  private static String ariaLift(int d) {
    return (d & 0x02) == 0 ? "maxed" : "between";
  }

  /** The distinct grip/lift states the SIPs since the last call show, in order. */
  private static List<String> states(ArcosTestClient c) {
    List<String> seen = new ArrayList<>();
    for (StandardSip s : c.sips()) {
      String st = ariaGrip(s.getDigIn()) + "/" + ariaLift(s.getDigIn());
      if (seen.isEmpty() || !seen.get(seen.size() - 1).equals(st)) {
        seen.add(st);
      }
    }
    c.clear();
    return seen;
  }

  @Test
  void gripperExampleSeesTheGripperOpenCloseAndLiftAsOnARobot() {
    try (SimWorld w = SimWorld.bundled("office", SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.clear();
      c.sendRaw(HEX.parseHex(REQUEST));
      ArRobotPacket first = c.awaitId(PacketIds.GRIPPER);
      first.resetRead();
      assertEquals(1, first.bufToUByte(), "type 1: ARIA takes it as a user-I/O gripper");
      c.sendRaw(HEX.parseHex(STOP));
      w.advanceMillis(200);
      c.clear();
      w.advanceMillis(1000);
      assertTrue(c.packets(PacketIds.GRIPPER).isEmpty(), "GRIPPERPACREQUEST 0 stops them");
      assertEquals(List.of("closed/maxed"), states(c));

      c.sendRaw(HEX.parseHex(OPEN));
      w.advanceMillis(4000);
      assertEquals(List.of("between/maxed", "open/maxed"), states(c));
      c.sendRaw(HEX.parseHex(LIFT_DOWN));
      w.advanceMillis(6000);
      assertEquals(List.of("open/between", "open/maxed"), states(c));
      c.sendRaw(HEX.parseHex(CLOSE));
      w.advanceMillis(4000);
      assertEquals(List.of("between/maxed", "closed/maxed"), states(c));
      c.sendRaw(HEX.parseHex(LIFT_UP));
      w.advanceMillis(6000);
      assertEquals(List.of("closed/between", "closed/maxed"), states(c));
    }
  }
}
