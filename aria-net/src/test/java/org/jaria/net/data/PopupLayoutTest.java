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

class PopupLayoutTest {

  private static final PopupInfo ASK =
      new PopupInfo(
          "goal",
          "Goal",
          "Go on?",
          PopupInfo.PopupType.QUESTION,
          0,
          1,
          30,
          "Nobody answered",
          "Yes",
          "Going on",
          "No",
          "Stopped",
          "",
          "");

  @Test
  void createAndCloseReadBack() {
    ArNetPacket p = new ArNetPacket();
    PopupLayout.writeCreate(p, 7, ASK);
    assertEquals(
        new PopupLayout.Shown(
            7,
            "goal",
            "Goal",
            "Go on?",
            PopupInfo.PopupType.QUESTION,
            List.of("Yes", "No", ""),
            0,
            1),
        PopupLayout.readCreate(p.toReader()));
    assertNull(PopupLayout.readCreate(new ArNetPacket().toReader()), "an empty packet");
    ArNetPacket c = new ArNetPacket();
    PopupLayout.writeClose(c, 7, "Going on");
    assertEquals(new PopupLayout.Closed(7, "Going on"), PopupLayout.readClose(c.toReader()));
  }

  @Test
  void theBytesAreArNetworkings() {
    ArNetPacket p = new ArNetPacket();
    PopupLayout.writeCreate(p, 258, PopupInfo.message("T", "m", PopupInfo.PopupType.WARNING));
    assertArrayEquals(
        new byte[] {2, 1, 0, 0, 0, 'T', 0, 'm', 0, 2, 'O', 'K', 0, 0, 0, 0, 0}, p.toByteArray());
    ArNetPacket clicked = new ArNetPacket();
    PopupLayout.writeClicked(clicked, 3, 1);
    assertArrayEquals(new byte[] {3, 0, 0, 0, 1}, clicked.toByteArray());
  }

  @Test
  void hostilePacketsAreErrors() {
    ArNetPacket whole = new ArNetPacket();
    PopupLayout.writeCreate(whole, 1, ASK);
    byte[] b = whole.toByteArray();
    for (int cut = 1; cut < b.length; cut++) {
      byte[] part = Arrays.copyOf(b, cut);
      assertThrows(
          ArNetPacketException.class,
          () -> PopupLayout.readCreate(ArNetPacket.wrap(part)),
          "cut at " + cut);
    }
    // A type out of range (9) is an error, not an icon.
    ArNetPacket bad = new ArNetPacket();
    bad.byte4ToBuf(1).strToBuf("").strToBuf("t").strToBuf("m").byteToBuf(9);
    bad.strToBuf("OK").strToBuf("").strToBuf("").byteToBuf(0).byteToBuf(0);
    assertThrows(ArNetPacketException.class, () -> PopupLayout.readCreate(bad.toReader()));
    assertThrows(
        ArNetPacketException.class,
        () -> PopupLayout.readClose(new ArNetPacket().byte4ToBuf(1).toReader()));
  }

  @Test
  void popupInfoChecksItsButtons() {
    assertThrows(
        IllegalArgumentException.class,
        () ->
            new PopupInfo(
                "", "", "", PopupInfo.PopupType.NOICON, 3, 0, 0, "", "", "", "", "", "", ""));
    assertThrows(IllegalArgumentException.class, () -> PopupInfo.PopupType.of(5));
    assertEquals("Popup closed because of odd click", ASK.pressedText(7));
    assertEquals("Stopped", ASK.pressedText(1));
  }
}
