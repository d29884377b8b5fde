package org.jaria.web.mcap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;
import org.jaria.geom.ArPose;
import org.jaria.web.foxglove.ChannelTable;
import org.jaria.web.foxglove.FrameEncoder;
import org.jaria.web.foxglove.Message;
import org.jaria.web.model.ClockFrame;
import org.jaria.web.model.LaserFrame;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.RobotStatus;
import org.jaria.web.model.WorldFrame;
import org.junit.jupiter.api.Test;

/**
 * The MCAP writer's bytes: their framing and checksums here, and a whole recording compared byte
 * for byte with {@code recording.mcap}, which was made by {@link #recording()} and then read by
 * hand with MCAP's official reader (@mcap/core 2.2.2, Node): McapIndexedReader read its 41 messages
 * on 11 channels through the summary's 2 chunk indexes, each payload JSON, and McapStreamReader
 * with CRC checks on read all 110 records (Header 1, Schema 16, Channel 22, Message 41,
 * MessageIndex 21, DataEnd 1, Statistics 1, ChunkIndex 2, SummaryOffset 4, Footer 1; schemas and
 * channels appear in the chunks and again in the summary).
 */
class McapWriterTest {

  /** A small run: the map, then four frames of one robot moving, as the web view records them. */
  static byte[] recording() throws IOException {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    try (McapRecorder rec = McapRecorder.to(out, "JAria test")) {
      ChannelTable table = new ChannelTable();
      MapLayer map =
          new MapLayer(
              "test",
              Points.of(0, 0, 4000, 0, 4000, 0, 4000, 3000),
              Points.of(1000, 1000),
              List.of(new MapLayer.Goal("Lab", "Goal", 3000, 2000, 0, false)),
              Points.EMPTY,
              List.of(),
              MapLayer.Bounds.around(Points.of(0, 0, 4000, 3000)));
      for (int i = 0; i < 4; i++) {
        long t = 1_000_000_000L + i * 100_000_000L;
        RobotFrame r =
            new RobotFrame(
                "robot",
                "p3dx-sh",
                new ArPose(1000 + 40 * i, 1500, 0),
                new ArPose(1005 + 40 * i, 1495, 1),
                Points.of(200, -150, 200, 150, -200, 150, -200, -150),
                Points.of(1000, 1500),
                Points.of(3000 - 40 * i, 1500),
                new LaserFrame(
                    new ArPose(1100 + 40 * i, 1500, 0),
                    -90,
                    45,
                    new int[] {1500, 2000, 2900, 2000, 1500}),
                Points.of(1000, 1500, 1010, 1490),
                Points.of(1000 + 40 * i, 1500, 3000, 2000),
                new ArPose(3000, 2000, 0),
                new RobotStatus(400, 0, 12.5, true, false, "going to the goal", 0.9));
        List<Message> ms = new java.util.ArrayList<>();
        ms.add(FrameEncoder.encodeMap(map, t));
        ms.addAll(
            FrameEncoder.encode(new WorldFrame(new ClockFrame(t, 1, false, true), List.of(r))));
        table.update(ms);
        for (Message m : ms) {
          if (i == 0 || !m.topic().equals("/map")) {
            rec.write(table.get(m.topic()), m);
          }
        }
        if (i == 1) {
          // a chunk boundary in the middle, as a long recording has
          rec.flushChunkForTest();
        }
      }
    }
    return out.toByteArray();
  }

  @Test
  void aRecordingIsByteForByteTheOneTheOfficialReaderAccepted() throws IOException {
    byte[] now = recording();
    byte[] validated;
    try (InputStream in = McapWriterTest.class.getResourceAsStream("recording.mcap")) {
      if (in == null) {
        Path p = Path.of("target", "recording.mcap");
        Files.write(p, now);
        fail("no recording.mcap next to this test; wrote " + p.toAbsolutePath() + " to check");
        return;
      }
      validated = in.readAllBytes();
    }
    assertArrayEquals(validated, now);
  }

  @Test
  void theFileStartsAndEndsWithTheMagicAndItsChecksumsHold() throws IOException {
    byte[] b = recording();
    assertArrayEquals(McapWriter.MAGIC, Arrays.copyOf(b, 8));
    assertArrayEquals(McapWriter.MAGIC, Arrays.copyOfRange(b, b.length - 8, b.length));
    ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
    int footer = b.length - 8 - 29;
    assertEquals(McapWriter.FOOTER, b[footer]);
    assertEquals(20, bb.getLong(footer + 1));
    long summaryStart = bb.getLong(footer + 9);
    long summaryCrc = bb.getInt(footer + 25) & 0xFFFFFFFFL;
    CRC32 crc = new CRC32();
    crc.update(b, (int) summaryStart, footer + 25 - (int) summaryStart);
    assertEquals(crc.getValue(), summaryCrc, "summary CRC");
    // the data end record sits just before the summary: its CRC covers everything before it
    int dataEnd = (int) summaryStart - 13;
    assertEquals(McapWriter.DATA_END, b[dataEnd]);
    CRC32 data = new CRC32();
    data.update(b, 0, dataEnd);
    assertEquals(data.getValue(), bb.getInt(dataEnd + 9) & 0xFFFFFFFFL, "data CRC");
    // the header names the library
    assertTrue(new String(b, 0, 64, StandardCharsets.ISO_8859_1).contains("JAria test"));
  }

  @Test
  void anEmptyRecordingIsStillAValidFile() throws IOException {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    new McapWriter(out, "", "x").close();
    byte[] b = out.toByteArray();
    assertArrayEquals(McapWriter.MAGIC, Arrays.copyOfRange(b, b.length - 8, b.length));
  }

  @Test
  void channelsNeedTheirSchemaAndMessagesTheirChannel() throws IOException {
    try (McapWriter w = new McapWriter(new ByteArrayOutputStream(), "", "x")) {
      assertThrows(IllegalArgumentException.class, () -> w.addChannel(1, "/a", "json", Map.of()));
      int s = w.addSchema("s", "jsonschema", new byte[] {'{', '}'});
      int c = w.addChannel(s, "/a", "json", Map.of());
      assertEquals(0, c);
      assertThrows(IllegalArgumentException.class, () -> w.write(5, 0, 0, new byte[0]));
    }
  }
}
