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
}
