package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.junit.jupiter.api.Test;

class ConfigLayoutTest {

  private static final ConfigSection TELEOP =
      new ConfigSection(
          "Teleop",
          "driving by hand",
          List.of(
              new ConfigParam("MaxSpeed", "DOUBLE", "500.0", "", "0.0", "2000.0", "mm/s"),
              new ConfigParam("Beeps", "INT", "3", "", "", "10", "how often"),
              new ConfigParam("Sonar", "BOOL", "true", "", "", "", "use the sonar"),
              new ConfigParam("Name", "STRING", "r1", "", "", "", "the robot's name")));

  @Test
  void sectionsReadBackFromTheJoinedPackets() {
    ArNetPacket out = new ArNetPacket();
    ConfigLayout.writeSection(out, TELEOP);
    ConfigLayout.writeSection(out, new ConfigSection("Empty", "", List.of()));
    assertEquals(
        List.of(TELEOP, new ConfigSection("Empty", "", List.of())),
        ConfigLayout.readAll(out.toReader()));
  }

  @Test
  void theBytesAreArNetworkings() {
    ArNetPacket out = new ArNetPacket();
    ConfigLayout.writeSection(
        out,
        new ConfigSection("S", "c", List.of(new ConfigParam("n", "INT", "7", "", "", "", "d"))));
    ArNetPacket in = out.toReader();
    assertEquals('S', in.bufToByte());
    assertEquals("S", in.bufToStr());
    assertEquals("c", in.bufToStr());
    assertEquals('P', in.bufToByte());
    assertEquals("n", in.bufToStr());
    assertEquals("d", in.bufToStr());
    assertEquals(0, in.bufToByte(), "priority");
    assertEquals('i', in.bufToByte());
    assertEquals(7, in.bufToByte4());
    assertEquals(Integer.MIN_VALUE, in.bufToByte4(), "no minimum");
    assertEquals(Integer.MAX_VALUE, in.bufToByte4(), "no maximum");
    assertEquals("", in.bufToStr(), "display hint");
  }

  @Test
  void garbageAndTruncatedPacketsAreRefused() {
    ArNetPacket junk = new ArNetPacket();
    junk.byteToBuf('Q');
    assertThrows(ArNetPacketException.class, () -> ConfigLayout.readAll(junk.toReader()));
    ArNetPacket out = new ArNetPacket();
    ConfigLayout.writeSection(out, TELEOP);
    byte[] all = out.toReader().remainingBytes();
    ArNetPacket cut = ArNetPacket.wrap(0, all, 0, all.length - 3);
    assertThrows(ArNetPacketException.class, () -> ConfigLayout.readAll(cut));
  }
}
