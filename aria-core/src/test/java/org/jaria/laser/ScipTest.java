package org.jaria.laser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.junit.jupiter.api.Test;

/** SCIP 2.0 encodings and answers against the strings Hokuyo's protocol description prints. */
class ScipTest {

  @Test
  void numbersEncodeAsInTheProtocolDescription() {
    assertEquals(1234, Scip.decode("CB", 0, 2));
    assertEquals(5432, Scip.decode("1Dh", 0, 3));
    assertEquals("CB", Scip.encode(1234, 2));
    assertEquals("1Dh", Scip.encode(5432, 3));
    assertEquals("000", Scip.encode(0, 3));
    assertArrayEquals(new int[] {5432, 1234}, Scip.decodeAll("1Dh" + "0CB", 3));
    assertThrows(IllegalArgumentException.class, () -> Scip.encode(4096, 2));
    assertThrows(IllegalArgumentException.class, () -> Scip.decode("0~", 0, 2));
  }

  @Test
  void statusAndInfoLinesCarryTheirPublishedChecksums() {
    assertEquals("00P", Scip.statusLine("00"));
    assertEquals("99b", Scip.statusLine("99"));
    assertEquals("PROT:SCIP 2.0;N", Scip.infoLine("PROT", "SCIP 2.0"));
    assertEquals(
        "VEND:Hokuyo Automatic Co.,Ltd.;[", Scip.infoLine("VEND", "Hokuyo Automatic Co.,Ltd."));
    assertEquals("AMAX:725;o", Scip.infoLine("AMAX", "725"));
    assertEquals("SCAN:600;e", Scip.infoLine("SCAN", "600"));
  }

  @Test
  void aParameterAnswerParses() {
    List<String> lines = new ArrayList<>(List.of("PP", "00P"));
    lines.addAll(List.of(UrgParams.URG_04LX.infoLines()));
    ScipBlock b = new ScipBlock(lines);
    assertEquals("00", b.status());
    UrgParams p = UrgParams.of(b.info());
    assertEquals(UrgParams.URG_04LX, p);
    assertEquals(0, p.angleOf(384), 1e-9);
    assertEquals(-90, p.angleOf(128), 1e-9);
    assertEquals(128, p.stepOf(-90));
    assertEquals(725, p.stepOf(170), "clamped to the last measurable step");
  }

  @Test
  void aDamagedInfoLineIsRefused() {
    ScipBlock b = new ScipBlock(List.of("PP", "00P", "DMAX:5600;X"));
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, b::info);
    assertEquals("bad checksum on 'DMAX:5600;X'", e.getMessage());
    assertEquals(Map.of(), new ScipBlock(List.of("PP", "00P", "junk")).info());
  }

  @Test
  void distanceLinesSplitAt64AndJoinBack() {
    StringBuilder enc = new StringBuilder();
    for (int i = 0; i < 30; i++) {
      enc.append(Scip.encode(1000 + i, 3));
    }
    List<String> data = Scip.dataLines(enc);
    assertEquals(2, data.size());
    assertEquals(65, data.get(0).length());
    List<String> lines =
        new ArrayList<>(List.of("MD0044072501000", "99b", "0000" + Scip.checksum("0000")));
    lines.addAll(data);
    ScipBlock b = new ScipBlock(lines);
    assertEquals("99", b.status());
    int[] d = Scip.decodeAll(b.joinedData(3), 3);
    assertEquals(30, d.length);
    assertEquals(1029, d[29]);
  }

  @Test
  void receiverCutsBlocksAndBoundsRunaways() {
    DropCounters drops = new DropCounters("test");
    ScipReceiver rx = new ScipReceiver(drops);
    List<ScipBlock> got = new ArrayList<>();
    String stream = "\nBM\r\n00P\r\n\r\nQT\n00P\n\n" + "X".repeat(300) + "\n\nVV\n00P\n\n";
    byte[] b = stream.getBytes(StandardCharsets.US_ASCII);
    for (byte x : b) {
      rx.feed(new byte[] {x}, 0, 1, got::add);
    }
    assertEquals(List.of("BM", "QT", "VV"), got.stream().map(ScipBlock::echo).toList());
    assertEquals(1, drops.get(DropReason.BAD_LENGTH), "the over-long line");
  }
}
