package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.PeerRecording;
import org.jaria.net.data.PopupInfo;
import org.jaria.net.data.PopupLayout;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/**
 * ARIA 2.9.1's popupExample (an ArNetworking server on a {@code jaria sim} robot that opens a popup
 * when a range reading comes within 0.5 m) and JAria's client, recorded by hand (see
 * docs/networking.md): the client drove the robot to a wall, got the popup, pressed its first
 * button, and ARIA's server closed the popup with that button's text ("a client closed popup dialog
 * window with id=1. Button=0... OK pressed." in its log). The replay plays the server's bytes to
 * ArClientBase and checks the popup it reads; the recorded client bytes show what JAria answered.
 */
class AriaPopupsReplayTest {

  @Test
  void theClientReadsPopupExamplesPopupAndItsClose() throws Exception {
    byte[] recorded = PeerRecording.bytes("popupExample.s2c.bin");
    List<ArNetPacket> packets = PeerRecording.packets(recorded);
    List<PopupLayout.Shown> shown = new CopyOnWriteArrayList<>();
    List<PopupLayout.Closed> closed = new CopyOnWriteArrayList<>();
    try (ServerSocket fake = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        ArClientBase c = new ArClientBase("monitor")) {
      Thread server =
          new Thread(
              () -> {
                try (Socket s = fake.accept()) {
                  OutputStream out = s.getOutputStream();
                  out.write(packets.get(0).toWire());
                  DataInputStream in = new DataInputStream(s.getInputStream());
                  byte[] h = new byte[4];
                  in.readFully(h);
                  in.readFully(new byte[((h[2] & 0xff) | (h[3] & 0xff) << 8) - 4]);
                  out.write(PeerRecording.from(recorded, 1));
                  out.flush();
                  while (in.read() >= 0) {
                    // until the client leaves
                  }
                } catch (Exception e) {
                  // the assertions report what went wrong
                }
              },
              "fake-popupExample");
      server.start();
      c.addHandler(
          "popupCreate",
          p -> {
            PopupLayout.Shown s = PopupLayout.readCreate(p);
            if (s != null) {
              shown.add(s);
            }
          });
      c.addHandler("popupClose", p -> closed.add(PopupLayout.readClose(p)));
      c.connect("127.0.0.1", fake.getLocalPort(), "", "");
      Eventually.until("the popup and its close", () -> shown.size() == 1 && closed.size() == 1);
      assertEquals(
          new PopupLayout.Shown(
              1,
              "popupExample",
              "Object Detected",
              "A range sensor detected a reading within 0.5 meters of the robot.",
              PopupInfo.PopupType.INFORMATION,
              List.of("OK", "Turn Around", "Shut Down"),
              0,
              0),
          shown.get(0));
      assertEquals(new PopupLayout.Closed(1, "Acknowleged."), closed.get(0));
      // ARIA's server ended popupList's answer with an empty popupList packet.
      int popupList = c.findCommandFromName("popupList");
      assertTrue(
          packets.stream().anyMatch(p -> p.getCommand() == popupList && p.getDataLength() == 0));
      // What JAria's client sent: popupClicked for popup 1, button 0, in ArNetworking's layout.
      int clicked = c.findCommandFromName("popupClicked");
      ArNetPacket sent =
          PeerRecording.packets(PeerRecording.bytes("popupExample.c2s.bin")).stream()
              .filter(p -> p.getCommand() == clicked)
              .findFirst()
              .orElseThrow();
      assertArrayEquals(new byte[] {1, 0, 0, 0, 0}, sent.toByteArray());
      assertEquals(
          Protocol.CLIENT_INTRODUCTION,
          PeerRecording.packets(PeerRecording.bytes("popupExample.c2s.bin")).get(0).getCommand());
      c.disconnect();
      server.join(5000);
    }
  }
}
