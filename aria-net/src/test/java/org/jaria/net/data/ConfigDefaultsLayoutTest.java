package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.junit.jupiter.api.Test;

class ConfigDefaultsLayoutTest {

  private static final List<ConfigSection> SECTIONS =
      List.of(
          new ConfigSection(
              "Teleop",
              "",
              List.of(
                  new ConfigParam("MaxSpeed", "DOUBLE", "800", "500", "0", "2000", "mm/s"),
                  new ConfigParam("Sonar", "BOOL", "false", "true", "", "", ""))),
          new ConfigSection(
              "Localization",
              "",
              List.of(new ConfigParam("NumSamples", "INT", "500", "2000", "10", "200000", ""))));

  @Test
  void everySectionOrOneReadsBack() {
    ArNetPacket all = new ArNetPacket();
    ConfigDefaultsLayout.write(all, SECTIONS, "");
    assertEquals(
        Map.of(
            "Teleop", Map.of("MaxSpeed", "500", "Sonar", "true"),
            "Localization", Map.of("NumSamples", "2000")),
        ConfigDefaultsLayout.read(all.toReader()));
    ArNetPacket one = new ArNetPacket();
    ConfigDefaultsLayout.write(one, SECTIONS, "localization");
    assertEquals(
        Map.of("Localization", Map.of("NumSamples", "2000")),
        ConfigDefaultsLayout.read(one.toReader()));
    ArNetPacket none = new ArNetPacket();
    ConfigDefaultsLayout.write(none, SECTIONS, "Nowhere");
    assertEquals(0, none.getDataLength(), "an unknown section sends nothing");
  }

  @Test
  void theBytesAreSetConfigsPairs() {
    ArNetPacket one = new ArNetPacket();
    ConfigDefaultsLayout.write(one, SECTIONS, "Localization");
    assertArrayEquals(
        "Section\0Localization\0NumSamples\u00002000\0".getBytes(StandardCharsets.US_ASCII),
        one.toByteArray());
  }

  @Test
  void hostilePacketsAreErrors() {
    // A parameter before any section, and a name without its value.
    ArNetPacket orphan = new ArNetPacket().strToBuf("MaxSpeed").strToBuf("1");
    assertThrows(ArNetPacketException.class, () -> ConfigDefaultsLayout.read(orphan.toReader()));
    ArNetPacket odd = new ArNetPacket().strToBuf("Section").strToBuf("S").strToBuf("lonely");
    assertThrows(ArNetPacketException.class, () -> ConfigDefaultsLayout.read(odd.toReader()));
    ArNetPacket unterminated = ArNetPacket.wrap(new byte[] {'S', 'e', 'c'});
    assertThrows(
        ArNetPacketException.class, () -> ConfigDefaultsLayout.read(unterminated.toReader()));
  }
}
