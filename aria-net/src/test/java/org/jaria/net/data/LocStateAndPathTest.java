package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.junit.jupiter.api.Test;

class LocStateAndPathTest {

  @Test
  void locStateIsAUbyteAndAUbyte2() {
    LocState s =
        LocState.of(
            new LocalizationSnapshot("LOCALIZATION_SUCCESS", 0.937, new ArPose(1, 2), 500, false));
    assertEquals(new LocState(2, 94), s);
    ArNetPacket p = new ArNetPacket();
    s.write(p);
    assertArrayEquals(new byte[] {2, 94, 0}, p.toByteArray());
    assertEquals(s, LocState.read(p.toReader()));
    assertEquals("LOCALIZATION_SUCCESS", s.stateName());
    assertEquals("STATE_9", new LocState(9, 0).stateName());
    // A score that is not a number, or out of 0..1, is clamped; an unknown state is 0.
    assertEquals(
        new LocState(0, 0),
        LocState.of(new LocalizationSnapshot("SOMETHING", Double.NaN, null, 0, true)));
    assertEquals(100, LocState.of(new LocalizationSnapshot("", 7, null, 0, true)).score());
  }

  @Test
  void hostileLocStatesAreErrors() {
    assertThrows(
        ArNetPacketException.class,
        () -> LocState.read(new ArNetPacket().uByteToBuf(1).uByte2ToBuf(101).toReader()));
    assertThrows(
        ArNetPacketException.class,
        () -> LocState.read(new ArNetPacket().uByteToBuf(1).toReader()));
  }

  @Test
  void pathIsAByte2CountAndPoints() {
    PathPoints path = new PathPoints(Points.ofFlat(new int[] {1, 2, -3, 4}, 2));
    ArNetPacket p = new ArNetPacket();
    path.write(p);
    assertArrayEquals(
        new byte[] {2, 0, 1, 0, 0, 0, 2, 0, 0, 0, -3, -1, -1, -1, 4, 0, 0, 0}, p.toByteArray());
    assertEquals(path, PathPoints.read(p.toReader()));
  }

  @Test
  void hostilePathsAreErrors() {
    assertThrows(
        ArNetPacketException.class,
        () -> PathPoints.read(new ArNetPacket().byte2ToBuf(30000).byte4ToBuf(1).toReader()));
    assertThrows(
        ArNetPacketException.class,
        () -> PathPoints.read(new ArNetPacket().byte2ToBuf(-2).toReader()));
    assertThrows(
        IllegalArgumentException.class,
        () -> new PathPoints(Points.ofFlat(new int[2 * (PathPoints.MAX_POINTS + 1)], 2)));
  }
}
