package org.jaria.laser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.jaria.protocol.DropCounters;
import org.junit.jupiter.api.Test;

/** SCIP 1.1 requests and answers, byte for byte (the forms ARIA's ArUrg sends and reads). */
class Scip11Test {

  private static List<ScipBlock> blocks(String stream) {
    List<ScipBlock> out = new ArrayList<>();
    byte[] b = stream.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    new ScipReceiver(new DropCounters("scip11-test")).feed(b, 0, b.length, out::add);
    return out;
  }

  @Test
  void requestsAreArias() {
    assertEquals("G12864001", Scip11.distanceRequest(128, 640, 1));
    assertEquals("G04472503", Scip11.distanceRequest(44, 725, 3));
    assertEquals("S1152007654321", Scip11.baudRequest(115200));
    assertThrows(IllegalArgumentException.class, () -> Scip11.distanceRequest(640, 128, 1));
  }

  @Test
  void aVersionAnswer() {
    ScipBlock v =
        blocks(
                """
                V
                0
                VEND:Hokuyo Automatic Co.,Ltd.
                PROD:SOKUIKI Sensor URG-04LX
                PROT:SCIP 1.1
                SERI:H0000000

                """)
            .get(0);
    assertEquals("V", v.echo());
    assertEquals("0", Scip11.status(v));
    Map<String, String> info = Scip11.info(v);
    assertEquals("SCIP 1.1", info.get("PROT"));
    assertEquals("Hokuyo Automatic Co.,Ltd.", info.get("VEND"));
  }

  @Test
  void aScanAnswerIsTwoCharactersADistanceAcrossLines() {
    // 1000 mm = 15·64 + 40 → "?X"; 2000 = 31·64 + 16 → "O@"; 4095 → "oo"; 33 values = 66 chars,
    // so the last value sits alone on the second line
    String line1 = "?X".repeat(31) + "O@";
    ScipBlock g = blocks("G00003201\n0\n" + line1 + "\noo\n\n").get(0);
    int[] d = Scip11.distances(g);
    assertEquals(33, d.length);
    assertEquals(1000, d[0]);
    assertEquals(2000, d[31]);
    assertEquals(4095, d[32]);
    assertEquals(List.of(line1, "oo"), Scip11.dataLines(line1 + "oo"));
    assertArrayEquals(new int[] {1000}, Scip11.distances(blocks("G0\n0\n?X\n\n").get(0)));
    assertThrows(
        IllegalArgumentException.class, () -> Scip11.distances(blocks("G\n0\n?X!\n\n").get(0)));
  }
}
