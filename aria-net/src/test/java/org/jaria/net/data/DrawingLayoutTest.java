package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Arrays;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.junit.jupiter.api.Test;

class DrawingLayoutTest {

  private static final NamedDrawing SONAR =
      new NamedDrawing(
          "sonarCurrent",
          ArDrawingData.of("polyArrows", ArDrawingData.color(0x33, 0xCC, 0xFF), 200, 70));
  private static final NamedDrawing PATH =
      new NamedDrawing(
          "path", new ArDrawingData("polyLine", 0xFF0000, 2, 55, 0, 0x00FF00, "DefaultOff"));

  @Test
  void listsAndPointsReadBack() {
    ArNetPacket list = new ArNetPacket();
    DrawingLayout.writeList(list, List.of(SONAR, PATH));
    List<NamedDrawing> read = DrawingLayout.readList(list.toReader());
    // listDrawings carries no visibility: it reads as DefaultOn.
    assertEquals(SONAR, read.get(0));
    assertEquals("DefaultOn", read.get(1).data().visibility());
    assertEquals(PATH.data().secondaryColor(), read.get(1).data().secondaryColor());

    ArNetPacket joined = new ArNetPacket();
    DrawingLayout.writeListed(joined, SONAR);
    DrawingLayout.writeListed(joined, PATH);
    assertEquals(List.of(SONAR, PATH), DrawingLayout.readAllListed(joined.toReader()));
    assertNull(DrawingLayout.readListed(new ArNetPacket().toReader()), "the empty end packet");

    Points pts = Points.ofFlat(new int[] {1, -2, 300000, -400000}, 2);
    ArNetPacket p = new ArNetPacket();
    DrawingLayout.writePoints(p, pts);
    assertEquals(pts, DrawingLayout.readPoints(p.toReader()));
  }

  @Test
  void theBytesAreArNetworkings() {
    ArNetPacket p = new ArNetPacket();
    DrawingLayout.writeListed(p, PATH);
    byte[] expected = {
      'p',
      'a',
      't',
      'h',
      0,
      'p',
      'o',
      'l',
      'y',
      'L',
      'i',
      'n',
      'e',
      0,
      0,
      0,
      (byte) 0xFF,
      0, // primary colour 0x00FF0000, little-endian
      2,
      0,
      0,
      0, // size
      55,
      0,
      0,
      0, // layer
      0,
      0,
      0,
      0, // refresh time
      0,
      (byte) 0xFF,
      0,
      0, // secondary colour
      'D',
      'e',
      'f',
      'a',
      'u',
      'l',
      't',
      'O',
      'f',
      'f',
      0
    };
    assertArrayEquals(expected, p.toByteArray());
    ArNetPacket pts = new ArNetPacket();
    DrawingLayout.writePoints(pts, Points.ofFlat(new int[] {-1, 2}, 2));
    assertArrayEquals(new byte[] {1, 0, 0, 0, -1, -1, -1, -1, 2, 0, 0, 0}, pts.toByteArray());
  }

  @Test
  void hostilePacketsAreErrorsNotHugeArrays() {
    // A count the packet cannot hold (it would allocate 2^31 points), a negative one, one cut
    // short.
    ArNetPacket huge = new ArNetPacket().byte4ToBuf(Integer.MAX_VALUE).byte4ToBuf(1);
    assertThrows(ArNetPacketException.class, () -> DrawingLayout.readPoints(huge.toReader()));
    ArNetPacket negative = new ArNetPacket().byte4ToBuf(-1);
    assertThrows(ArNetPacketException.class, () -> DrawingLayout.readPoints(negative.toReader()));
    assertThrows(ArNetPacketException.class, () -> DrawingLayout.readList(negative.toReader()));
    ArNetPacket manyListed = new ArNetPacket().byte4ToBuf(1_000_000);
    assertThrows(ArNetPacketException.class, () -> DrawingLayout.readList(manyListed.toReader()));
    ArNetPacket whole = new ArNetPacket();
    DrawingLayout.writeListed(whole, PATH);
    byte[] b = whole.toByteArray();
    for (int cut = 1; cut < b.length; cut++) {
      byte[] part = Arrays.copyOf(b, cut);
      assertThrows(
          ArNetPacketException.class,
          () -> DrawingLayout.readListed(ArNetPacket.wrap(part)),
          "cut at " + cut);
    }
    // Text where numbers belong: the strings run into the numbers and leave the packet short.
    ArNetPacket words = new ArNetPacket().strToBuf("a").strToBuf("b").strToBuf("c");
    assertThrows(ArNetPacketException.class, () -> DrawingLayout.readListed(words.toReader()));
  }

  @Test
  void drawingDataChecksItsRefreshTime() {
    assertThrows(
        IllegalArgumentException.class,
        () -> new ArDrawingData("polyDots", 0, 1, 50, -1, 0, "DefaultOn"));
    assertEquals(0x33CCFF, ArDrawingData.color(0x33, 0xCC, 0xFF));
  }
}
