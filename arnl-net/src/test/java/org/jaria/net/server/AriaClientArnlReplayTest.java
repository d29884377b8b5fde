package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.jaria.net.ArNetPacket;
import org.jaria.net.PeerRecording;
import org.jaria.net.RawClient;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.RobotUpdate;
import org.junit.jupiter.api.Test;

/**
 * Replays the bytes ARIA 2.9.1's own clients sent to {@code jaria demo guiserver} (recorded by
 * hand, see docs/networking.md) to a JAria guiServer with SonARNL's localization and path planning,
 * as the demo had, and checks what it answers. The recordings are aria-net's (its test jar).
 */
class AriaClientArnlReplayTest {

  @Test
  void clientStringInfoExampleGetsTheLabelsAndTheStrings() throws Exception {
    byte[] sent = PeerRecording.bytes("clientStringInfoExample.c2s.bin");
    // Introduction, UDP confirmation, updateStrings (-1) and updateNumbers (100 ms), getStringsInfo
    // once, then getStrings every second.
    assertEquals(
        List.of(2, 4, 129, 129, 291, 129),
        PeerRecording.packets(sent).stream().map(ArNetPacket::getCommand).toList());
    // By hand it printed "Robot cycle (ms)   Network clients   Localization score" as its
    // columns, then rows such as "0.22   1   0.938": the recorded answers say the same.
    List<ArNetPacket> answered =
        PeerRecording.packets(PeerRecording.bytes("clientStringInfoExample.s2c.bin"));
    ArNetPacket infoThen =
        answered.stream().filter(p -> p.getCommand() == 291).findFirst().orElseThrow().toReader();
    assertEquals(
        List.of("Robot cycle (ms)", "Network clients", "Localization score"),
        org.jaria.net.data.InfoStrings.readLabels(infoThen));
    org.jaria.net.provider.VideoSource camera = namedCamera(null);
    try (ArnlRig rig = ArnlRig.arnl(b -> b.video(camera));
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      assertEquals(291, s.findCommandFromName("getStringsInfo"));
      assertEquals(270, s.findCommandFromName("getStrings"));
      aria.readIntroduction();
      aria.send(sent);
      // getStrings is answered at once and getStringsInfo by a worker: either may come first.
      var answers = aria.readUntilAll(291, 270);
      List<String> labels = org.jaria.net.data.InfoStrings.readLabels(answers.get(291));
      assertEquals(List.of("Robot cycle (ms)", "Network clients", "Localization score"), labels);
      org.jaria.net.data.InfoStrings strings =
          org.jaria.net.data.InfoStrings.read(answers.get(270), labels);
      assertEquals("2", strings.get("Network clients"), "the rig's own client and ARIA's");
      assertEquals(3, strings.values().size());
    }
  }

  @Test
  void clientDemoGetsItsTableAndDrives() throws Exception {
    byte[] sent = PeerRecording.bytes("clientDemo.c2s.bin");
    List<ArNetPacket> asSent = PeerRecording.packets(sent);
    // Its introduction, UDP confirmation, setSafeDrive 1, batteryInfo and physicalInfo once,
    // then updateNumbers every 100 ms and updateStrings and mapUpdated when they change.
    assertEquals(
        List.of(2, 4, 284, 261, 260, 129, 129, 129),
        asSent.stream().map(ArNetPacket::getCommand).toList());
    // The demo guiServer it talked to: localization, planning and a camera.
    org.jaria.net.provider.VideoSource camera = namedCamera(null);
    try (ArnlRig rig = ArnlRig.arnl(b -> b.video(camera));
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      for (var e :
          java.util.Map.of(
                  258, "updateNumbers",
                  259, "updateStrings",
                  260, "batteryInfo",
                  261, "physicalInfo",
                  267, "mapUpdated",
                  284, "setSafeDrive")
              .entrySet()) {
        assertEquals(e.getKey(), s.findCommandFromName(e.getValue()), e.getValue());
      }
      aria.readIntroduction();
      aria.send(sent);
      // physicalInfo and batteryInfo are answered by different threads: take them in either order.
      java.util.Map<Integer, ArNetPacket> got = new java.util.HashMap<>();
      while (!got.containsKey(261) || !got.containsKey(260)) {
        ArNetPacket p = aria.read();
        got.putIfAbsent(p.getCommand(), p);
      }
      ArNetPacket physical = got.get(261);
      assertEquals(rig.robot.getRobotType(), physical.bufToStr());
      ArNetPacket battery = got.get(260);
      assertEquals(11.5, battery.bufToDouble());
      assertEquals(11, battery.bufToDouble());
      rig.run(300);
      RobotUpdate u = RobotUpdate.readNumbers(aria.readUntil(258), "", "");
      assertEquals((int) rig.robot.getX(), (int) u.x(), 50);
    }
  }

  @Test
  void getVideoExampleSavesAJpegFromSendVideo() throws Exception {
    byte[] sent = PeerRecording.bytes("getVideoExample.c2s.bin");
    List<ArNetPacket> asSent = PeerRecording.packets(sent);
    // Introduction, UDP confirmation, then sendVideo once (it has no getPictureCam1 to use).
    assertEquals(List.of(2, 4, 277), asSent.stream().map(ArNetPacket::getCommand).toList());
    byte[] rgb = new byte[160 * 120 * 3];
    java.util.Arrays.fill(rgb, (byte) 120);
    org.jaria.net.data.VideoFrame frame =
        new org.jaria.net.data.VideoFrame(
            1, org.jaria.net.data.VideoFrame.Format.RGB, 160, 120, rgb);
    org.jaria.net.provider.VideoSource camera = namedCamera(frame);
    try (ArnlRig rig = ArnlRig.arnl(b -> b.video(camera));
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      assertEquals(277, rig.gui.getServer().findCommandFromName("sendVideo"));
      aria.readIntroduction();
      aria.send(sent);
      ArNetPacket video = aria.readUntil(277);
      assertEquals(160, video.bufToUByte2());
      assertEquals(120, video.bufToUByte2());
      byte[] jpeg = video.bufToData(video.getRemaining());
      java.awt.image.BufferedImage img =
          javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(jpeg));
      assertEquals(160, img.getWidth(), "a JPEG the example can save");
      // What it saved by hand: a 160x120 JPEG of about 2 kB from the simulated camera.
      List<ArNetPacket> answered =
          PeerRecording.packets(PeerRecording.bytes("getVideoExample.s2c.bin"));
      ArNetPacket then =
          answered.stream().filter(p -> p.getCommand() == 277).findFirst().orElseThrow();
      assertEquals(160, then.bufToUByte2());
      assertEquals(120, then.bufToUByte2());
    }
  }

  @Test
  void configClientReadsTheConfigurationBySections() throws Exception {
    byte[] sent = PeerRecording.bytes("configClient.c2s.bin");
    List<ArNetPacket> asSent = PeerRecording.packets(sent);
    // ARIA's configClient: introduction, UDP confirmation, then getConfigBySections (its only
    // choice here: this server offers none of the later versions).
    int asked = asSent.get(asSent.size() - 1).getCommand();
    try (ArnlRig rig = ArnlRig.arnl();
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      assertEquals(asked, s.findCommandFromName("getConfigBySections"), "the number it requested");
      aria.readIntroduction();
      aria.send(sent);
      java.io.ByteArrayOutputStream joined = new java.io.ByteArrayOutputStream();
      int packets = 0;
      while (true) {
        ArNetPacket p = aria.readUntil(asked);
        if (p.getDataLength() == 0) {
          break; // RETURN_UNTIL_EMPTY: the empty packet ends the answer
        }
        packets++;
        joined.writeBytes(p.remainingBytes());
      }
      byte[] all = joined.toByteArray();
      List<org.jaria.net.data.ConfigSection> sections =
          org.jaria.net.data.ConfigLayout.readAll(ArNetPacket.wrap(asked, all, 0, all.length));
      assertEquals(sections.size(), packets, "one packet per section");
      org.jaria.net.data.ConfigSection loc =
          sections.stream().filter(x -> x.name().equals("Localization")).findFirst().orElseThrow();
      assertTrue(
          loc.params().stream()
              .anyMatch(q -> q.name().equals("NumSamples") && q.min().equals("10")),
          loc.params().toString());
    }
  }

  @Test
  void configClientGetsTheConfigurationAndItsDefaults() throws Exception {
    byte[] sent = PeerRecording.bytes("configClientDefaults.c2s.bin");
    List<ArNetPacket> asSent = PeerRecording.packets(sent);
    // Introduction, UDP confirmation, getConfigBySections, then getConfigDefaults (the server
    // lists it, so ArClientHandlerConfig can request the defaults).
    assertEquals(4, asSent.size());
    int bySections = asSent.get(2).getCommand();
    int defaults = asSent.get(3).getCommand();
    // By hand, JAria's client had set NumSamples to 700 first: configClient.txt said 700 and
    // configClientDefaults.txt 2000. The recorded answers say the same.
    List<ArNetPacket> answered =
        PeerRecording.packets(PeerRecording.bytes("configClientDefaults.s2c.bin"));
    ArNetPacket defaultsThen =
        answered.stream().filter(p -> p.getCommand() == defaults).findFirst().orElseThrow();
    assertEquals(
        "2000",
        org.jaria.net.data.ConfigDefaultsLayout.read(defaultsThen.toReader())
            .get("Localization")
            .get("NumSamples"));
    org.jaria.net.provider.VideoSource camera = namedCamera(null);
    try (ArnlRig rig = ArnlRig.arnl(b -> b.video(camera));
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      assertEquals(bySections, s.findCommandFromName("getConfigBySections"));
      assertEquals(defaults, s.findCommandFromName("getConfigDefaults"), "the number it used");
      assertEquals(
          "", rig.call("setConfig", "Section", "Localization", "NumSamples", "700").bufToStr());
      aria.readIntroduction();
      aria.send(sent);
      java.util.Map<String, java.util.Map<String, String>> got =
          org.jaria.net.data.ConfigDefaultsLayout.read(aria.readUntil(defaults));
      assertEquals("2000", got.get("Localization").get("NumSamples"));
      assertTrue(got.keySet().containsAll(List.of("Localization")), got.keySet().toString());
    }
  }

  @Test
  void changeMapOnServerChangesTheMap() throws Exception {
    byte[] c2s = PeerRecording.bytes("changeMapOnServer.c2s.bin");
    byte[] s2c = PeerRecording.bytes("changeMapOnServer.s2c.bin");
    Map<Integer, String> then = PeerRecording.listedCommands(PeerRecording.packets(s2c));
    List<ArNetPacket> sent = PeerRecording.packets(c2s);
    ArNetPacket setConfig = sent.get(sent.size() - 1).toReader();
    assertEquals("setConfig", then.get(setConfig.getCommand()));
    // "Got configuration from server. Changing map to hall", "Saving...": Files/Map first.
    assertEquals("Section", setConfig.bufToStr());
    assertEquals("Files", setConfig.bufToStr());
    assertEquals("Map", setConfig.bufToStr());
    assertEquals("hall", setConfig.bufToStr());
    try (ArnlRig rig = ArnlRig.arnl();
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      aria.readIntroduction();
      aria.send(PeerRecording.renumbered(c2s, s2c, s::findCommandFromName));
      int bySections = s.findCommandFromName("getConfigBySections");
      int set = s.findCommandFromName("setConfig");
      Map<Integer, ArNetPacket> got =
          AriaClientControlReplayTest.readStepping(rig, aria, bySections, set);
      assertEquals(
          "Files", ConfigLayout.readAll(got.get(bySections)).get(0).name(), "what it looks for");
      ArNetPacket answer = got.get(set);
      assertEquals("", answer.bufToStr(), "every value taken");
      assertEquals("hall", rig.gui.getMapName());
      assertEquals(
          org.jaria.map.ArMap.loadBundled("hall").getLines().size(),
          rig.nav.getPathPlanningTask().getAriaMap().getLines().size());
    }
  }

  /**
   * A camera named "Camera" showing {@code frame} (null: no picture yet). The demo guiServer the
   * recordings talked to had one, and its video data take part in the data numbers.
   */
  private static org.jaria.net.provider.VideoSource namedCamera(
      org.jaria.net.data.VideoFrame frame) {
    return new org.jaria.net.provider.VideoSource() {
      @Override
      public String getName() {
        return "Camera";
      }

      @Override
      public org.jaria.net.data.VideoFrame getLatestFrame() {
        return frame;
      }
    };
  }
}
