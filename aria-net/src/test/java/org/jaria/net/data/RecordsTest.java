package org.jaria.net.data;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.function.Function;
import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;
import org.junit.jupiter.api.Test;

/**
 * Every message record reads back what it wrote, skips fields a newer server appends, and turns
 * garbage into an {@link ArNetPacketException} (the client's reader catches exactly that).
 */
class RecordsTest {

  private static ArNetPacket enc(NetEncodable v) {
    ArNetPacket p = new ArNetPacket();
    v.write(p);
    return p.toReader();
  }

  private static final List<NetEncodable> SAMPLES =
      List.of(
          new RobotUpdate(
              "Goto", "Going", 12.5, 1, -2, 90, 300, -10, 290, 310, true, false, true, false, 1,
              77),
          new PhysicalInfo("r", "Pioneer", "p3dx-sh", 381, 210, 210, 250, 16, 1500, 360),
          new MapData("office.map", 3, "2D-Map\nDATA\n"),
          new LocalizationSnapshot("LOCALIZATION_SUCCESS", 0.8, new ArPose(1, 2, 3), 500, false),
          new Particles(9, Points.ofFlat(new int[] {1, 2, 3, 4, 5, 6}, 3)),
          new PathSnapshot(
              "MOVING_TO_GOAL",
              "Going to 'Lab'",
              new ArPose(10, 20, 0),
              Points.ofFlat(new int[] {0, 0, 10, 20}, 2),
              Points.EMPTY),
          new RangeReadings("sonar", 5000, Points.ofFlat(new int[] {100, 200}, 2)),
          new SensorReadings(
              4, List.of(new RangeReadings("sonar", 5000, Points.ofFlat(new int[] {1, 1}, 2)))),
          new InfoStrings(List.of("Score"), List.of("0.9")),
          new CommandInfo("say", "logs", "string"),
          new ConfigParam("NumSamples", "INT", "500", "2000", "10", "", "particles"),
          new ConfigSection(
              "Localization",
              "sonar",
              List.of(new ConfigParam("A", "BOOL", "true", "false", "", "", ""))),
          new DataInfo(4, "update", "state", "none", "RobotUpdate", "RobotInfo", true),
          new VideoFrame(2, VideoFrame.Format.RGB, 2, 1, new byte[] {1, 2, 3, 4, 5, 6}));

  private static final List<Function<ArNetPacket, Object>> READERS =
      List.of(
          RobotUpdate::read,
          PhysicalInfo::read,
          MapData::read,
          LocalizationSnapshot::read,
          Particles::read,
          PathSnapshot::read,
          RangeReadings::read,
          SensorReadings::read,
          InfoStrings::read,
          CommandInfo::read,
          ConfigParam::read,
          ConfigSection::read,
          DataInfo::read,
          VideoFrame::read);

  @Test
  void everyRecordReadsBackWhatItWrote() {
    for (int i = 0; i < SAMPLES.size(); i++) {
      ArNetPacket p = enc(SAMPLES.get(i));
      Object back = READERS.get(i).apply(p);
      assertEquals(SAMPLES.get(i), back, SAMPLES.get(i).getClass().getSimpleName());
      assertFalse(p.hasMore(), "every byte read");
    }
  }

  @Test
  void newerServersMayAppendFields() {
    // A RobotUpdate with one more field (say, a future "temperature") still reads.
    ArNetPacket p = new ArNetPacket().arrayToBuf(17);
    p.strToBuf("Stop").strToBuf("Stopped");
    for (int i = 0; i < 8; i++) {
      p.doubleToBuf(i);
    }
    p.boolToBuf(true).boolToBuf(false).boolToBuf(false).boolToBuf(false);
    p.intToBuf(0).intToBuf(5).doubleToBuf(36.6);
    ArNetPacket r = p.toReader();
    RobotUpdate u = RobotUpdate.read(r);
    assertEquals(5, u.counter());
    assertFalse(r.hasMore());
  }

  @Test
  void tooFewFieldsIsAClearError() {
    ArNetPacket p = new ArNetPacket().arrayToBuf(2).strToBuf("a").strToBuf("b");
    ArNetPacketException e =
        assertThrows(ArNetPacketException.class, () -> CommandInfo.read(p.toReader()));
    assertEquals("a command needs 3 fields, has 2", e.getMessage());
    ArNetPacket bad = new ArNetPacket().arrayToBuf(2).intToBuf(4).intsToBuf(new int[5], 5);
    assertThrows(ArNetPacketException.class, () -> Points.read(bad.toReader()), "stride 4");
    ArNetPacket rgb =
        new ArNetPacket()
            .arrayToBuf(5)
            .intToBuf(1)
            .strToBuf("RGB")
            .intToBuf(100)
            .intToBuf(100)
            .dataToBuf(new byte[3]);
    assertThrows(ArNetPacketException.class, () -> VideoFrame.read(rgb.toReader()), "size");
  }

  @Test
  void mutatedRecordsGiveOnlyPacketErrors() {
    Random rnd = new Random(13);
    int refused = 0;
    for (int round = 0; round < 3000; round++) {
      int k = rnd.nextInt(SAMPLES.size());
      byte[] b = enc(SAMPLES.get(k)).toByteArray();
      int flips = 1 + rnd.nextInt(4);
      for (int f = 0; f < flips; f++) {
        b[rnd.nextInt(b.length)] = (byte) rnd.nextInt(256);
      }
      if (rnd.nextBoolean()) {
        b = java.util.Arrays.copyOf(b, rnd.nextInt(b.length + 1));
      }
      try {
        Object unused = READERS.get(k).apply(ArNetPacket.wrap(b));
      } catch (ArNetPacketException e) {
        refused++;
      }
    }
    assertTrue(refused > 1000, "most mutations are refused: " + refused);
  }

  @Test
  void pointsKeepHeadingsAndBuildFromPoses() {
    Points p = Points.of(List.of(new ArPose(1.4, 2.6, 89.6)), true);
    assertEquals(1, p.size());
    assertTrue(p.hasHeadings());
    assertEquals(1, p.x(0));
    assertEquals(3, p.y(0));
    assertEquals(90, p.th(0));
    assertEquals(List.of(new ArPose(1, 3, 90)), p.toPoses());
    assertArrayEquals(new int[0], new int[Points.EMPTY.size()]);
    assertThrows(IllegalArgumentException.class, () -> Points.ofFlat(new int[] {1, 2, 3}, 2));
  }
}
