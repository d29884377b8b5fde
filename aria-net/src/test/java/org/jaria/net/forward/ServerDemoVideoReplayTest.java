package org.jaria.net.forward;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.PeerRecording;
import org.jaria.net.RecordedServer;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ServerOptions;
import org.junit.jupiter.api.Test;

/**
 * JAria's forwarder against ARIA 2.9.1's serverDemo, itself forwarding {@code jaria acts}'s SAV
 * video with ARIA's ArHybridForwarderVideo (recorded by hand, docs/networking.md: the first 12
 * packets serverDemo sent to {@code jaria demo guiserver --forward-video 127.0.0.1:PORT}).
 */
class ServerDemoVideoReplayTest {

  @Test
  void theForwarderPassesOnServerDemosFramesByteForByte() throws Exception {
    List<ArNetPacket> recorded =
        PeerRecording.packets(PeerRecording.bytes("serverDemo-video.s2c.bin"));
    // serverDemo lists ARIA's forwarder's data among its own: videoSize 332, sendVideo 333.
    List<String> names = PeerRecording.listedNames(recorded);
    assertEquals(332 - 256, names.indexOf("videoSize"));
    assertEquals(333 - 256, names.indexOf("sendVideo"));
    List<byte[]> frames =
        recorded.stream().filter(p -> p.getCommand() == 333).map(ArNetPacket::toByteArray).toList();
    assertFalse(frames.isEmpty(), "serverDemo sent frames");
    // What the JAria forwarder asked serverDemo by hand: videoSize once, sendVideo with a quality.
    List<ArNetPacket> asked =
        PeerRecording.packets(PeerRecording.bytes("serverDemo-video.c2s.bin"));
    assertEquals(332, asked.get(2).getCommand());
    assertEquals(333, asked.get(3).getCommand());
    assertEquals(ArHybridForwarderVideo.FIRST_QUALITY, asked.get(3).toReader().bufToUByte());
    try (RecordedServer serverDemo = new RecordedServer("serverDemo-video.s2c.bin")) {
      ArServerBase robot = new ArServerBase(ServerOptions.builder().port(0).build());
      try (ArHybridForwarderVideo video =
              new ArHybridForwarderVideo(
                  robot,
                  "127.0.0.1",
                  serverDemo.getPort(),
                  Duration.ofSeconds(5),
                  System::nanoTime);
          ArClientBase viewer = new ArClientBase("getVideoExample")) {
        robot.open();
        viewer.connect("127.0.0.1", robot.getPort(), "", "");
        Eventually.until("serverDemo's first frame", () -> video.getStats().frames() >= 1);
        byte[] got = viewer.requestOnce("sendVideo").get().remainingBytes();
        // The latest frame is passed on: which one depends on how far the replay has got (it
        // was the first until a loaded machine let the forwarder read on before the request).
        assertTrue(
            frames.stream().anyMatch(f -> Arrays.equals(f, got)),
            "byte for byte one of the frames serverDemo sent (" + got.length + " bytes)");
        assertEquals(160, (got[0] & 0xff) | (got[1] & 0xff) << 8);
        assertEquals(
            160,
            ImageIO.read(new ByteArrayInputStream(got, 4, got.length - 4)).getWidth(),
            "a JPEG getVideoExample can save");
        ArNetPacket size = viewer.requestOnce("videoSize").get();
        assertEquals(160, size.bufToUByte2(), "serverDemo's videoSize, passed on");
        assertEquals(120, size.bufToUByte2());
        assertEquals(0, video.getStats().dropped());
        assertTrue(video.isForwardingVideo());
      } finally {
        robot.close();
      }
    }
  }
}
