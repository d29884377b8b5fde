package org.jaria.web.mcap;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;

/**
 * Writes an MCAP file (the recording format Foxglove and Lichtblick open): the magic, a header,
 * then uncompressed chunks of schema, channel and message records each followed by its message
 * indexes, then a summary (schemas, channels, statistics, chunk indexes, summary offsets) and the
 * footer, with the data and summary CRCs, so that a reader can seek by time. Written here because
 * no maintained MCAP writer for Java is published on Maven Central; the format is small and
 * documented (its records are framed as opcode, uint64 length, content, all little-endian).
 *
 * <p>Not thread-safe; one thread writes.
 */
public final class McapWriter implements AutoCloseable {

  /** The file's first and last eight bytes. */
  static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

  static final int HEADER = 0x01;
  static final int FOOTER = 0x02;
  static final int SCHEMA = 0x03;
  static final int CHANNEL = 0x04;
  static final int MESSAGE = 0x05;
  static final int CHUNK = 0x06;
  static final int MESSAGE_INDEX = 0x07;
  static final int CHUNK_INDEX = 0x08;
  static final int STATISTICS = 0x0B;
  static final int SUMMARY_OFFSET = 0x0E;
  static final int DATA_END = 0x0F;

  /** A chunk is closed once its records reach this size. */
  static final int CHUNK_BYTES = 1 << 20;

  // Private and written once: the array is never handed out.
  @SuppressWarnings("ArrayRecordComponent")
  private record SchemaRec(int id, String name, String encoding, byte[] data) {}

  private record ChannelRec(
      int id, int schemaId, String topic, String encoding, Map<String, String> metadata) {}

  private record ChunkIndex(
      long start,
      long end,
      long offset,
      long length,
      Map<Integer, Long> indexOffsets,
      long indexLength,
      long size) {}

  private final OutputStream out;
  private final CRC32 dataCrc = new CRC32();
  private final Records rec = new Records(4096);
  private final Records chunk = new Records(CHUNK_BYTES + 65536);
  private final Map<Integer, List<long[]>> chunkIndex = new TreeMap<>();
  private final List<SchemaRec> schemas = new ArrayList<>();
  private final List<ChannelRec> channels = new ArrayList<>();
  private final Map<Integer, Long> channelCounts = new TreeMap<>();
  private final List<ChunkIndex> chunkIndexes = new ArrayList<>();
  private long position;
  private long chunkStart = Long.MAX_VALUE;
  private long chunkEnd = Long.MIN_VALUE;
  private long messageCount;
  private long firstTime = Long.MAX_VALUE;
  private long lastTime = Long.MIN_VALUE;
  private final Map<Integer, Integer> sequence = new LinkedHashMap<>();
  private boolean closed;

  /**
   * Starts a file: the magic and the header.
   *
   * @param profile the profile ("" for none; this server's messages are JSON)
   * @param library who wrote it
   */
  public McapWriter(OutputStream out, String profile, String library) throws IOException {
    this.out = out;
    emit(MAGIC, MAGIC.length, true);
    rec.reset();
    int at = rec.beginRecord(HEADER);
    rec.string(profile).string(library);
    rec.endRecord(at);
    emit(rec.array(), rec.size(), true);
  }

  /** Adds a schema; returns its id (1, 2, ...). */
  public int addSchema(String name, String encoding, byte[] data) {
    SchemaRec s = new SchemaRec(schemas.size() + 1, name, encoding, data.clone());
    schemas.add(s);
    writeSchema(chunk, s);
    return s.id();
  }

  /** Adds a channel on schema {@code schemaId}; returns its id (0, 1, ...). */
  public int addChannel(
      int schemaId, String topic, String messageEncoding, Map<String, String> metadata) {
    if (schemaId < 1 || schemaId > schemas.size()) {
      throw new IllegalArgumentException("no schema " + schemaId + ": add the schema first");
    }
    ChannelRec c =
        new ChannelRec(channels.size(), schemaId, topic, messageEncoding, Map.copyOf(metadata));
    channels.add(c);
    channelCounts.put(c.id(), 0L);
    writeChannel(chunk, c);
    return c.id();
  }

  /**
   * Adds a message.
   *
   * @param logTime when it was recorded, ns
   * @param publishTime when it was published, ns
   */
  public void write(int channelId, long logTime, long publishTime, byte[] data) throws IOException {
    if (channelId < 0 || channelId >= channels.size()) {
      throw new IllegalArgumentException("no channel " + channelId + ": add the channel first");
    }
    int seq = sequence.merge(channelId, 1, Integer::sum);
    chunkIndex
        .computeIfAbsent(channelId, k -> new ArrayList<>())
        .add(new long[] {logTime, chunk.size()});
    int at = chunk.beginRecord(MESSAGE);
    chunk.u16(channelId).u32(seq).u64(logTime).u64(publishTime).bytes(data);
    chunk.endRecord(at);
    chunkStart = Math.min(chunkStart, logTime);
    chunkEnd = Math.max(chunkEnd, logTime);
    firstTime = Math.min(firstTime, logTime);
    lastTime = Math.max(lastTime, logTime);
    messageCount++;
    channelCounts.merge(channelId, 1L, Long::sum);
    if (chunk.size() >= CHUNK_BYTES) {
      flushChunk();
    }
  }

  /** Bytes written to the stream so far. */
  public long position() {
    return position;
  }

  /** Writes the chunk so far (and its message indexes), if it holds anything. */
  void flushChunk() throws IOException {
    if (chunk.size() == 0) {
      return;
    }
    long start = chunkStart == Long.MAX_VALUE ? 0 : chunkStart;
    long end = chunkEnd == Long.MIN_VALUE ? 0 : chunkEnd;
    CRC32 crc = new CRC32();
    crc.update(chunk.array(), 0, chunk.size());
    long offset = position;
    rec.reset();
    int at = rec.beginRecord(CHUNK);
    rec.u64(start).u64(end).u64(chunk.size()).u32(crc.getValue()).string("").u64(chunk.size());
    rec.bytes(chunk.array(), 0, chunk.size());
    long length = rec.endRecord(at);
    emit(rec.array(), rec.size(), true);
    Map<Integer, Long> indexOffsets = new TreeMap<>();
    long indexStart = position;
    for (var e : chunkIndex.entrySet()) {
      indexOffsets.put(e.getKey(), position);
      rec.reset();
      int mi = rec.beginRecord(MESSAGE_INDEX);
      rec.u16(e.getKey()).u32(16L * e.getValue().size());
      for (long[] r : e.getValue()) {
        rec.u64(r[0]).u64(r[1]);
      }
      rec.endRecord(mi);
      emit(rec.array(), rec.size(), true);
    }
    chunkIndexes.add(
        new ChunkIndex(
            start, end, offset, length, indexOffsets, position - indexStart, chunk.size()));
    chunk.reset();
    chunkIndex.clear();
    chunkStart = Long.MAX_VALUE;
    chunkEnd = Long.MIN_VALUE;
  }

  private static void writeSchema(Records r, SchemaRec s) {
    int at = r.beginRecord(SCHEMA);
    r.u16(s.id()).string(s.name()).string(s.encoding()).u32(s.data().length).bytes(s.data());
    r.endRecord(at);
  }

  private static void writeChannel(Records r, ChannelRec c) {
    int at = r.beginRecord(CHANNEL);
    r.u16(c.id()).u16(c.schemaId()).string(c.topic()).string(c.encoding()).stringMap(c.metadata());
    r.endRecord(at);
  }

  private void emit(byte[] b, int len, boolean data) throws IOException {
    out.write(b, 0, len);
    if (data) {
      dataCrc.update(b, 0, len);
    }
    position += len;
  }

  /** Ends the file: the last chunk, the data end, the summary, the footer and the magic. */
  @Override
  public void close() throws IOException {
    if (closed) {
      return;
    }
    closed = true;
    try {
      flushChunk();
      rec.reset();
      int at = rec.beginRecord(DATA_END);
      rec.u32(dataCrc.getValue());
      rec.endRecord(at);
      emit(rec.array(), rec.size(), false);
      writeSummaryAndFooter();
      out.flush();
    } finally {
      out.close();
    }
  }

  private void writeSummaryAndFooter() throws IOException {
    CRC32 summaryCrc = new CRC32();
    long summaryStart = position;
    Records s = new Records(4096);
    List<long[]> groups = new ArrayList<>(); // opcode, start, length
    long groupStart = summaryStart;
    for (SchemaRec sc : schemas) {
      writeSchema(s, sc);
    }
    groups.add(new long[] {SCHEMA, groupStart, s.size()});
    int mark = s.size();
    for (ChannelRec c : channels) {
      writeChannel(s, c);
    }
    groups.add(new long[] {CHANNEL, summaryStart + mark, s.size() - mark});
    mark = s.size();
    int at = s.beginRecord(STATISTICS);
    s.u64(messageCount)
        .u16(schemas.size())
        .u32(channels.size())
        .u32(0)
        .u32(0)
        .u32(chunkIndexes.size())
        .u64(messageCount == 0 ? 0 : firstTime)
        .u64(messageCount == 0 ? 0 : lastTime);
    int mapAt = s.size();
    s.u32(0);
    for (var e : channelCounts.entrySet()) {
      s.u16(e.getKey()).u64(e.getValue());
    }
    s.patch32(mapAt, s.size() - mapAt - 4);
    s.endRecord(at);
    groups.add(new long[] {STATISTICS, summaryStart + mark, s.size() - mark});
    mark = s.size();
    for (ChunkIndex ci : chunkIndexes) {
      int c = s.beginRecord(CHUNK_INDEX);
      s.u64(ci.start()).u64(ci.end()).u64(ci.offset()).u64(ci.length());
      s.u32(10L * ci.indexOffsets().size());
      for (var e : ci.indexOffsets().entrySet()) {
        s.u16(e.getKey()).u64(e.getValue());
      }
      s.u64(ci.indexLength()).string("").u64(ci.size()).u64(ci.size());
      s.endRecord(c);
    }
    if (!chunkIndexes.isEmpty()) {
      groups.add(new long[] {CHUNK_INDEX, summaryStart + mark, s.size() - mark});
    }
    long summaryOffsetStart = summaryStart + s.size();
    for (long[] g : groups) {
      int o = s.beginRecord(SUMMARY_OFFSET);
      s.u8((int) g[0]).u64(g[1]).u64(g[2]);
      s.endRecord(o);
    }
    s.u8(FOOTER).u64(20).u64(summaryStart).u64(summaryOffsetStart);
    summaryCrc.update(s.array(), 0, s.size());
    s.u32(summaryCrc.getValue());
    emit(s.array(), s.size(), false);
    emit(MAGIC, MAGIC.length, false);
  }
}
