package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.ByteArrayOutputStream;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.junit.jupiter.api.Test;

class MapBinaryLayoutTest {

  private static final String MAP =
      "2D-Map\nMinPos: 0 0\nCairn: Goal 10 20 0 \"\" ICON \"A\"\nLINES\n0 0 100 0\nDATA\n5 6\n-7 8\n";

  private static ArNetPacket joined(List<ArNetPacket> bodies) {
    ByteArrayOutputStream b = new ByteArrayOutputStream();
    bodies.forEach(p -> b.writeBytes(p.toByteArray()));
    return ArNetPacket.wrap(b.toByteArray());
  }

  @Test
  void theTextReadsBack() {
    assertEquals(MAP, MapBinaryLayout.readText(joined(MapBinaryLayout.bodies(MAP))));
  }

  @Test
  void thePacketsAreArNetworkings() {
    List<ArNetPacket> b = MapBinaryLayout.bodies(MAP);
    // 3 header lines, LINES, one packet of lines, count 0, DATA, one packet of points, count 0.
    assertEquals(9, b.size());
    assertArrayEquals(
        "LINES\0".getBytes(java.nio.charset.StandardCharsets.US_ASCII), b.get(3).toByteArray());
    assertArrayEquals(
        new byte[] {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 100, 0, 0, 0, 0, 0, 0, 0},
        b.get(4).toByteArray());
    assertArrayEquals(new byte[] {0, 0, 0, 0}, b.get(5).toByteArray());
    assertArrayEquals(
        new byte[] {2, 0, 0, 0, 5, 0, 0, 0, 6, 0, 0, 0, -7, -1, -1, -1, 8, 0, 0, 0},
        b.get(7).toByteArray());
  }

  @Test
  void manyPointsAreSplitByAThousand() {
    StringBuilder m = new StringBuilder("2D-Map\nDATA\n");
    for (int i = 0; i < 2500; i++) {
      m.append(i).append(' ').append(-i).append('\n');
    }
    List<ArNetPacket> b = MapBinaryLayout.bodies(m.toString());
    assertEquals(1000, b.get(2).toReader().bufToByte4());
    assertEquals(500, b.get(4).toReader().bufToByte4());
    assertEquals(0, b.get(5).toReader().bufToByte4());
  }

  @Test
  void hostileAnswersAreErrors() {
    ArNetPacket huge = new ArNetPacket().strToBuf("DATA").byte4ToBuf(1 << 30);
    assertThrows(ArNetPacketException.class, () -> MapBinaryLayout.readText(huge.toReader()));
    ArNetPacket negative = new ArNetPacket().strToBuf("LINES").byte4ToBuf(-5);
    assertThrows(ArNetPacketException.class, () -> MapBinaryLayout.readText(negative.toReader()));
    ArNetPacket unended = new ArNetPacket().strToBuf("DATA").byte4ToBuf(1).byte4ToBuf(1);
    assertThrows(ArNetPacketException.class, () -> MapBinaryLayout.readText(unended.toReader()));
    assertThrows(
        IllegalArgumentException.class, () -> MapBinaryLayout.bodies("2D-Map\nDATA\nx y\n"));
  }
}
