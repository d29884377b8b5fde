package org.jaria.web.mcap;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.jaria.web.foxglove.Channel;
import org.jaria.web.foxglove.Message;
import org.jaria.web.server.MessageSink;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Records every message the web view publishes into an MCAP file, with the same topics, schemas and
 * JSON as the live channels, so Foxglove or Lichtblick replays a run as it looked live. A write
 * that fails (a full disk) ends the recording with a warning; the live view goes on.
 */
public final class McapRecorder implements MessageSink {

  private static final Logger LOG = LoggerFactory.getLogger(McapRecorder.class);

  private final McapWriter writer;
  private final Path file;
  private final Map<String, Integer> schemaIds = new HashMap<>();
  private final Map<Integer, Integer> channelIds = new HashMap<>();
  private boolean failed;

  private McapRecorder(McapWriter writer, Path file) {
    this.writer = writer;
    this.file = file;
  }

  /**
   * Creates (or replaces) {@code file}.
   *
   * @throws IOException if it cannot be created
   */
  public static McapRecorder create(Path file, String library) throws IOException {
    OutputStream out = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16);
    try {
      return new McapRecorder(new McapWriter(out, "", library), file);
    } catch (IOException e) {
      out.close();
      throw e;
    }
  }

  /** A recorder writing to {@code out} (tests). */
  public static McapRecorder to(OutputStream out, String library) throws IOException {
    return new McapRecorder(new McapWriter(out, "", library), null);
  }

  @Override
  public synchronized void write(Channel channel, Message message) {
    if (failed) {
      return;
    }
    int id =
        channelIds.computeIfAbsent(
            channel.id(),
            k -> {
              int schema =
                  schemaIds.computeIfAbsent(
                      channel.kind().schemaName(),
                      name ->
                          writer.addSchema(
                              name,
                              Channel.SCHEMA_ENCODING,
                              channel.kind().schema().getBytes(StandardCharsets.UTF_8)));
              return writer.addChannel(schema, channel.topic(), Channel.ENCODING, Map.of());
            });
    try {
      writer.write(id, message.timeNanos(), message.timeNanos(), message.payload());
    } catch (IOException e) {
      failed = true;
      LOG.warn("recording to {} stopped: {}", file, e.toString());
    }
  }

  /** Closes the current chunk now (tests: a recording with more than one chunk). */
  synchronized void flushChunkForTest() throws IOException {
    writer.flushChunk();
  }

  /** Bytes written so far. */
  public synchronized long bytesWritten() {
    return writer.position();
  }

  @Override
  public synchronized void close() {
    try {
      writer.close();
    } catch (IOException e) {
      throw new UncheckedIOException("could not finish the recording " + file, e);
    }
  }
}
