package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Arrays;
import java.util.List;
import java.util.function.Function;
import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;
import org.junit.jupiter.api.Test;

/**
 * Round trips of the layouts that are JAria's own (data ArNetworking has no layout for, see
 * PROTOCOL.md §8): what a record writes, its reader reads back equal, to the last byte; and a
 * packet cut short anywhere is an error, never a half-read value.
 */
class RecordsTest {

  private static final Points PATH =
      Points.of(List.of(new ArPose(0, 0), new ArPose(1500, -250), new ArPose(-3000, 4200)));

  private static <T extends NetEncodable> void roundTrip(T value, Function<ArNetPacket, T> reader) {
    ArNetPacket out = new ArNetPacket(300);
    value.write(out);
    ArNetPacket in = out.toReader();
    assertEquals(value, reader.apply(in));
    assertFalse(in.hasMore(), "read to the last byte: " + value);
    byte[] body = out.toByteArray();
    for (int cut = 0; cut < body.length; cut++) {
      ArNetPacket shortOne = new ArNetPacket(300);
      shortOne.dataToBuf(Arrays.copyOf(body, cut));
      ArNetPacket r = shortOne.toReader();
      int at = cut;
      assertThrows(ArNetPacketException.class, () -> reader.apply(r), "cut after " + at + " bytes");
    }
  }

  @Test
  void configSectionsAndParameters() {
    ConfigParam p =
        new ConfigParam("NumSamples", "INT", "2000", "2000", "10", "", "particles of the filter");
    roundTrip(p, ConfigParam::read);
    ConfigSection s = new ConfigSection("Localization", "sonar localization", List.of(p, p));
    roundTrip(s, ConfigSection::read);
    ArNetPacket out = new ArNetPacket(300);
    ConfigSection.writeAll(out, List.of(s, new ConfigSection("Empty", "", List.of())));
    assertEquals(
        List.of(s, new ConfigSection("Empty", "", List.of())),
        ConfigSection.readAll(out.toReader()));
  }

  @Test
  void localizationParticlesAndPath() {
    roundTrip(
        new LocalizationSnapshot("LOCALIZED", 0.875, new ArPose(1200, -300, 45), 2000, false),
        LocalizationSnapshot::read);
    roundTrip(new Particles(17, PATH), Particles::read);
    roundTrip(
        new PathSnapshot(
            "MOVING_TO_GOAL",
            "Going to Goal1",
            new ArPose(5000, 1000, 90),
            PATH,
            Points.of(List.of(new ArPose(10, 20)))),
        PathSnapshot::read);
  }

  @Test
  void liveMapsFitOnePacketHoweverLarge() {
    roundTrip(LiveMap.NONE, LiveMap::read);
    roundTrip(
        LiveMap.of(
            "scanning lab.2d",
            "lab.2d",
            12,
            new int[] {1, 2, 3, 4},
            new int[] {0, 0},
            new ArPose(10, 20, 30)),
        LiveMap::read);
    int[] many = new int[2 * 50_000];
    for (int i = 0; i < many.length; i++) {
      many[i] = i;
    }
    LiveMap big = LiveMap.of("", "big.2d", 9999, many, many, null);
    assertEquals(LiveMap.MAX_POINTS, big.points().size());
    assertEquals(LiveMap.MAX_PATH, big.path().size());
    assertEquals(many[many.length - 1], big.points().y(LiveMap.MAX_POINTS - 1), "the last kept");
    ArNetPacket p = new ArNetPacket(300);
    big.write(p); // throws if it does not fit one packet
    roundTrip(big, LiveMap::read);
  }

  @Test
  void videoFrames() {
    byte[] rgb = new byte[4 * 3 * 3];
    Arrays.fill(rgb, (byte) 200);
    roundTrip(new VideoFrame(7, VideoFrame.Format.RGB, 4, 3, rgb), VideoFrame::read);
    roundTrip(
        new VideoFrame(8, VideoFrame.Format.JPEG, 160, 120, new byte[] {(byte) 0xff, (byte) 0xd8}),
        VideoFrame::read);
  }
}
