package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.PeerRecording;
import org.jaria.net.RecordedServer;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigParam;
import org.jaria.net.data.ConfigSection;
import org.junit.jupiter.api.Test;

/**
 * ARIA 2.9.1's configServerRobot (a P3-DX's parameters served with ArServerHandlerConfig) and
 * serverDemo (its own configuration), played back as recorded by hand (docs/networking.md) to
 * JAria's client reading its configuration the way the monitor does, setting a value and reading it
 * back.
 */
class AriaConfigServerReplayTest {

  @Test
  void theClientReadsSetsAndRereadsConfigServerRobotsConfiguration() throws Exception {
    List<ArNetPacket> recorded =
        PeerRecording.packets(PeerRecording.bytes("configServerRobot.s2c.bin"));
    assertEquals(21, PeerRecording.listedNames(recorded).size(), "its data list");
    try (RecordedServer server = new RecordedServer("configServerRobot.s2c.bin");
        ArClientBase c = new ArClientBase("monitor")) {
      c.connect("127.0.0.1", server.getPort(), "", "");
      assertEquals(266, c.findCommandFromName("getConfigBySections"));
      List<ConfigSection> before = ConfigLayout.readAll(c.requestOnce("getConfigBySections").get());
      // 30 sections; the first has no name (configServerRobot's empty root section).
      assertEquals(30, before.size());
      assertEquals("", before.get(0).name());
      assertEquals("2200", param(before, "General settings", "MaxVelocity").value());
      assertEquals("250.0", param(before, "General settings", "RobotRadius").value());
      assertEquals("true", param(before, "General settings", "Holonomic").value());
      // Separators ('.' records) are not parameters: the section holds only values to edit.
      ConfigSection sonar = section(before, "SonarBoard_1");
      assertTrue(sonar.params().stream().noneMatch(p -> p.name().isEmpty()), sonar.toString());
      assertEquals(10, sonar.params().size());
      ArNetPacket answer =
          c.requestOnce("setConfig", "Section", "General settings", "MaxVelocity", "1800").get();
      assertEquals("", answer.bufToStr(), "configServerRobot took it (an empty refusal)");
      List<ConfigSection> after = ConfigLayout.readAll(c.requestOnce("getConfigBySections").get());
      assertEquals("1800", param(after, "General settings", "MaxVelocity").value());
    }
    // What JAria's client sent for setConfig, as ARIA's server read it.
    List<ArNetPacket> sent =
        PeerRecording.packets(PeerRecording.bytes("configServerRobot.c2s.bin"));
    ArNetPacket set = sent.get(3).toReader();
    assertEquals(268, set.getCommand());
    assertEquals(
        List.of("Section", "General settings", "MaxVelocity", "1800"),
        List.of(set.bufToStr(), set.bufToStr(), set.bufToStr(), set.bufToStr()));
  }

  @Test
  void theClientReadsAndSetsServerDemosConfiguration() throws Exception {
    try (RecordedServer server = new RecordedServer("serverDemoConfig.s2c.bin");
        ArClientBase c = new ArClientBase("monitor")) {
      c.connect("127.0.0.1", server.getPort(), "", "");
      List<ConfigSection> before = ConfigLayout.readAll(c.requestOnce("getConfigBySections").get());
      assertEquals(
          List.of(
              "Data logging",
              "Connection timeouts",
              "Jog Robot Position",
              "LogConfig",
              "Teleop settings"),
          before.stream().map(ConfigSection::name).toList());
      assertEquals(35, section(before, "Teleop settings").params().size());
      ConfigParam interval = param(before, "Data logging", "DataLogInterval");
      assertEquals("0", interval.value());
      assertEquals("0", interval.min(), "ARIA's range, read from its three integers");
      ArNetPacket answer =
          c.requestOnce("setConfig", "Section", "Data logging", "DataLogInterval", "1").get();
      assertEquals("", answer.bufToStr());
      List<ConfigSection> after = ConfigLayout.readAll(c.requestOnce("getConfigBySections").get());
      assertEquals("1", param(after, "Data logging", "DataLogInterval").value());
    }
  }

  private static ConfigSection section(List<ConfigSection> all, String name) {
    return all.stream().filter(s -> s.name().equals(name)).findFirst().orElseThrow();
  }

  private static ConfigParam param(List<ConfigSection> all, String section, String name) {
    return section(all, section).params().stream()
        .filter(p -> p.name().equals(name))
        .findFirst()
        .orElseThrow();
  }
}
