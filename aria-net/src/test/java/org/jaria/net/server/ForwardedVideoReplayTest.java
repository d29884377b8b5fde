package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.PeerRecording;
import org.jaria.net.RawClient;
import org.jaria.net.data.VideoFrame;
import org.jaria.net.forward.ArHybridForwarderVideo;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.provider.VideoSource;
import org.jaria.net.server.info.ArServerHandlerVideo;
import org.junit.jupiter.api.Test;

/**
 * Replays what ARIA 2.9.1's getVideoExample sent by hand to {@code jaria demo guiserver
 * --forward-video} (docs/networking.md) to a guiServer forwarding a video server's frames, and
 * checks it gets those frames. The recorded data numbers are matched by name, so the recordings
 * stay valid when services are added to the guiServer.
 */
class ForwardedVideoReplayTest {

  @Test
  void getVideoExampleSavesTheForwardedFrame() throws Exception {
    byte[] sent = PeerRecording.bytes("getVideoExample-forwarded.c2s.bin");
    byte[] answered = PeerRecording.bytes("getVideoExample-forwarded.s2c.bin");
    // Introduction, UDP confirmation, sendVideo once (the guiServer has no getPictureCam1).
    List<ArNetPacket> asSent = PeerRecording.packets(sent);
    assertEquals(3, asSent.size());
    assertEquals(
        "sendVideo",
        PeerRecording.listedCommands(PeerRecording.packets(answered))
            .get(asSent.get(2).getCommand()));
    // By hand it wrote "a 160x120 image, 4061 bytes" from jaria acts' desk scene.
    ArNetPacket then =
        PeerRecording.packets(answered).stream()
            .filter(p -> p.getCommand() == asSent.get(2).getCommand())
            .findFirst()
            .orElseThrow();
    assertEquals(160, then.bufToUByte2());
    assertEquals(120, then.bufToUByte2());
    assertEquals(4061, then.getRemaining());
    List<ArNetPacket> frames = replay(sent, answered, 1);
    assertEquals(1, frames.size());
  }

  @Test
  void getVideoExampleAtTwoFramesASecondGetsFrameAfterFrame() throws Exception {
    byte[] sent = PeerRecording.bytes("getVideoExample-chain.c2s.bin");
    byte[] answered = PeerRecording.bytes("getVideoExample-chain.s2c.bin");
    // -rate 2: a REQUEST of sendVideo every 500 ms (by hand through serverDemo's forwarder).
    ArNetPacket request = PeerRecording.packets(sent).get(2);
    assertEquals(Protocol.CLIENT_REQUEST, request.getCommand());
    ArNetPacket r = request.toReader();
    assertEquals(
        "sendVideo",
        PeerRecording.listedCommands(PeerRecording.packets(answered)).get(r.bufToUByte2()));
    assertEquals(500, r.bufToByte4());
    assertTrue(replay(sent, answered, 3).size() >= 3);
  }

  /** Sends {@code sent}, renumbered, to a forwarding guiServer; returns the first frames. */
  private static List<ArNetPacket> replay(byte[] sent, byte[] answered, int frames)
      throws Exception {
    byte[] jpeg = jpeg();
    VideoSource camera =
        new VideoSource() {
          final VideoFrame f = new VideoFrame(1, VideoFrame.Format.JPEG, 160, 120, jpeg);

          @Override
          public String getName() {
            return "SAV";
          }

          @Override
          public VideoFrame getLatestFrame() {
            return f;
          }
        };
    ArServerBase sav = new ArServerBase(ServerOptions.builder().port(0).build());
    new ArServerHandlerVideo(sav, camera);
    sav.open();
    try (GuiRig rig = GuiRig.plain(b -> b);
        ArHybridForwarderVideo video =
            new ArHybridForwarderVideo(rig.gui.getServer(), "127.0.0.1", sav.getPort())) {
      ArServerBase s = rig.gui.getServer();
      Eventually.until("the forwarder's first frame", () -> video.getStats().frames() >= 1);
      try (RawClient aria = new RawClient(s.getPort())) {
        aria.readIntroduction();
        aria.send(PeerRecording.renumbered(sent, answered, s::findCommandFromName));
        int sendVideo = s.findCommandFromName("sendVideo");
        List<ArNetPacket> got = new java.util.ArrayList<>();
        while (got.size() < frames) {
          ArNetPacket p = aria.readUntil(sendVideo);
          assertEquals(160, p.bufToUByte2());
          assertEquals(120, p.bufToUByte2());
          assertArrayEquals(jpeg, p.bufToData(p.getRemaining()), "the video server's JPEG");
          got.add(p);
        }
        return got;
      }
    } finally {
      sav.close();
    }
  }

  private static byte[] jpeg() throws Exception {
    BufferedImage img = new BufferedImage(160, 120, BufferedImage.TYPE_INT_RGB);
    img.getGraphics().fillRect(40, 30, 80, 60);
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ImageIO.write(img, "jpg", out);
    byte[] b = out.toByteArray();
    return Arrays.copyOf(b, b.length);
  }
}
