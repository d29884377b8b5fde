package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.PeerRecording;
import org.jaria.net.RawClient;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/**
 * Replays the bytes ARIA 2.9.1's own clients sent to {@code jaria demo guiserver} (recorded by
 * hand, see docs/networking.md) to a JAria guiServer, and checks what it answers.
 */
class AriaClientReplayTest {

  @Test
  void robotUpdateExampleLogsInAndGetsUpdateNumbersAndStrings() throws Exception {
    byte[] sent = PeerRecording.bytes("robotUpdateExample.c2s.bin");
    List<ArNetPacket> asSent = PeerRecording.packets(sent);
    // What ARIA's client sent: introduction, UDP confirmation, then two requests.
    assertEquals(
        List.of(Protocol.CLIENT_INTRODUCTION, Protocol.CLIENT_UDP_CONFIRMATION, 129, 129),
        asSent.stream().map(ArNetPacket::getCommand).toList());
    try (GuiRig rig = GuiRig.plain(b -> b);
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      assertEquals(258, s.findCommandFromName("updateNumbers"), "the number it requested");
      assertEquals(259, s.findCommandFromName("updateStrings"));
      aria.readIntroduction();
      aria.send(sent);
      assertEquals(
          Protocol.SERVER_CONNECTED, aria.readUntil(Protocol.SERVER_CONNECTED).getCommand());
      rig.run(500);
      ArNetPacket strings = aria.readUntil(259);
      assertEquals("Stopped", strings.bufToStr());
      assertEquals("Stop", strings.bufToStr());
      ArNetPacket numbers = aria.readUntil(258);
      RobotUpdate u = RobotUpdate.readNumbers(numbers, "Stop", "Stopped");
      assertEquals((int) rig.robot.getX(), (int) u.x(), 50);
      assertEquals((int) rig.robot.getY(), (int) u.y(), 50);
    }
  }

  @Test
  void clientCommandListerSeesTheServicesItListed() throws Exception {
    byte[] sent = PeerRecording.bytes("clientCommandLister.c2s.bin");
    List<String> listedThen =
        PeerRecording.listedNames(
            PeerRecording.packets(PeerRecording.bytes("clientCommandLister.s2c.bin")));
    assertTrue(
        listedThen.containsAll(
            List.of("update", "ratioDrive", "listCommands", "listStringCommands", "enableMotors")),
        listedThen.toString());
    try (GuiRig rig = GuiRig.plain(b -> b);
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      aria.readIntroduction();
      aria.send(PeerRecording.packets(sent).get(0).toWire());
      aria.readUntil(Protocol.SERVER_CONNECTED);
      ArNetPacket list = aria.readUntil(Protocol.SERVER_LIST);
      List<String> now = PeerRecording.listedNames(List.of(list));
      for (String name :
          List.of(
              "update",
              "updateNumbers",
              "updateStrings",
              "physicalInfo",
              "batteryInfo",
              "ratioDrive",
              "stop",
              "getGoals",
              "getMapName",
              "getMap")) {
        assertTrue(now.contains(name), name + " is listed: " + now);
      }
      // The recording came from the full demo (camera, localization, config): a plain guiServer
      // lists a part of it, with the same names, up to getStringsInfo; the data added since
      // (drawings, popups, home, dock ...) come after it, keeping the recorded numbers.
      List<String> recordedPart = now.subList(0, now.indexOf("getStringsInfo") + 1);
      assertTrue(
          listedThen.containsAll(recordedPart),
          "listed by hand: " + listedThen + ", now: " + recordedPart);
      assertTrue(
          now.indexOf("listDrawings") > now.indexOf("getStringsInfo")
              && now.indexOf("popupCreate") > now.indexOf("getStringsInfo"),
          now.toString());
      assertTrue(aria.readUntil(Protocol.SERVER_LIST_ARGRET).bufToUByte2() > 0);
      assertTrue(aria.readUntil(Protocol.SERVER_LIST_GROUP_AND_FLAGS).bufToUByte2() > 0);
    }
  }

  @Test
  void anAriaClientListsAndRunsTheSimpleCommands() throws Exception {
    // The login clientCommandLister sent by hand, then what ArNetworking's client sends for
    // listCommands and for a simple command: a packet of the data's number with an empty body.
    byte[] intro =
        PeerRecording.packets(PeerRecording.bytes("clientCommandLister.c2s.bin")).get(0).toWire();
    try (GuiRig rig = GuiRig.plain(b -> b);
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      int list = s.findCommandFromName("listCommands");
      aria.readIntroduction();
      aria.send(intro);
      aria.readUntil(Protocol.SERVER_CONNECTED);
      aria.send(new ArNetPacket(list));
      ArNetPacket p = aria.readUntil(list);
      assertEquals(2, p.bufToByte2(), "byte2 count");
      assertEquals("enableMotors", p.bufToStr());
      assertEquals("switches the motors on", p.bufToStr());
      assertEquals("disableMotors", p.bufToStr());
      assertEquals("switches the motors off", p.bufToStr());
      assertEquals(0, p.getRemaining());
      // Each command is followed by listCommands: the list's answer is the next packet (the
      // command, RETURN_NONE as in ArNetworking, answers nothing) and shows that the server has
      // queued the command for the robot's cycle, which the test then runs.
      for (String command : List.of("disableMotors", "enableMotors")) {
        aria.send(new ArNetPacket(s.findCommandFromName(command)));
        aria.send(new ArNetPacket(list));
        assertEquals(list, aria.read().getCommand(), command + " answers nothing");
        rig.run(300);
        assertEquals(command.equals("enableMotors"), rig.robot.areMotorsEnabled(), command);
      }
    }
  }

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
    try (GuiRig rig = GuiRig.arnl(b -> b.video(camera));
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
    try (GuiRig rig = GuiRig.arnl(b -> b.video(camera));
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
    try (GuiRig rig = GuiRig.arnl(b -> b.video(camera));
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
    try (GuiRig rig = GuiRig.arnl();
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
    try (GuiRig rig = GuiRig.arnl(b -> b.video(camera));
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
