package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.PeerRecording;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/**
 * Plays back what ARIA 2.9.1's serverDemo sent to the JAria monitor's client (recorded by hand, see
 * docs/networking.md) and checks that ArClientBase logs in, learns the data list and reads the
 * robot's updates.
 */
class AriaServerReplayTest {

  @Test
  void theClientReadsServerDemo() throws Exception {
    byte[] recorded = PeerRecording.bytes("serverDemo.s2c.bin");
    List<ArNetPacket> packets = PeerRecording.packets(recorded);
    assertEquals(Protocol.SERVER_INTRODUCTION, packets.get(0).getCommand());
    AtomicReference<byte[]> clientIntro = new AtomicReference<>();
    try (ServerSocket fake = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        ArClientBase c = new ArClientBase("monitor")) {
      Thread server =
          new Thread(
              () -> {
                try (Socket s = fake.accept()) {
                  OutputStream out = s.getOutputStream();
                  out.write(packets.get(0).toWire());
                  out.flush();
                  DataInputStream in = new DataInputStream(s.getInputStream());
                  byte[] h = new byte[4];
                  in.readFully(h);
                  int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
                  byte[] w = new byte[len];
                  System.arraycopy(h, 0, w, 0, 4);
                  in.readFully(w, 4, len - 4);
                  clientIntro.set(w);
                  out.write(PeerRecording.from(recorded, 1));
                  out.flush();
                  while (in.read() >= 0) {
                    // until the client leaves
                  }
                } catch (Exception e) {
                  // the test's assertions report what went wrong
                }
              },
              "fake-serverDemo");
      server.start();
      AtomicReference<RobotUpdate> update = new AtomicReference<>();
      c.addHandler("update", p -> update.set(RobotUpdate.read(p)));
      c.connect("127.0.0.1", fake.getLocalPort(), "", "");
      assertEquals(
          PeerRecording.listedNames(packets).size(), c.getDataList().size(), "the whole list");
      assertEquals(265, c.findCommandFromName("update"));
      assertEquals(280, c.findCommandFromName("ratioDrive"));
      assertTrue(
          c.getDataList().stream().anyMatch(d -> d.name().equals("stop") && d.returnsNothing()));
      Eventually.until("serverDemo's update", () -> update.get() != null);
      // The recording was made while the monitor drove serverDemo's robot.
      assertTrue(List.of("Stop", "Drive").contains(update.get().mode()), update.get().mode());
      // The client's introduction as ARIA's server reads it: udp port, user, digest, version, type.
      ArNetPacket intro = ArNetPacket.fromWire(clientIntro.get(), 0, clientIntro.get().length);
      assertEquals(Protocol.CLIENT_INTRODUCTION, intro.getCommand());
      assertEquals(0, intro.bufToUByte2());
      assertEquals("", intro.bufToStr());
      assertEquals(16, intro.bufToData(16).length);
      assertEquals(Protocol.JARIA_ACK_VERSION, intro.bufToStr());
      assertEquals(0, intro.bufToByte());
      c.disconnect();
      server.join(5000);
    }
  }
}
