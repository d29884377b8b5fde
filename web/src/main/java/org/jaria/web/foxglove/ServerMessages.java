package org.jaria.web.foxglove;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.Map;
import org.jaria.web.json.Json;

/**
 * What the server says in Foxglove's WebSocket protocol ({@code foxglove.websocket.v1}): JSON text
 * messages (serverInfo, advertise, unadvertise, status) and binary ones (message data, time), as
 * plain functions of their contents.
 */
public final class ServerMessages {

  /** The WebSocket subprotocol of Foxglove's protocol. */
  public static final String SUBPROTOCOL = "foxglove.websocket.v1";

  /** Binary opcode of a message on a subscription. */
  public static final byte MESSAGE_DATA = 1;

  /** Binary opcode of the server's time. */
  public static final byte TIME = 2;

  /** Status levels. */
  public enum Level {
    /** For information. */
    INFO,
    /** Something was refused or dropped. */
    WARNING,
    /** Something failed. */
    ERROR
  }

  private ServerMessages() {}

  /** The first message to a client: the server's name, what it can do, and facts for the page. */
  public static String serverInfo(
      String name, List<String> capabilities, Map<String, String> metadata, String sessionId) {
    return Json.string(
        g -> {
          g.writeStartObject();
          g.writeStringField("op", "serverInfo");
          g.writeStringField("name", name);
          g.writeArrayFieldStart("capabilities");
          for (String c : capabilities) {
            g.writeString(c);
          }
          g.writeEndArray();
          g.writeArrayFieldStart("supportedEncodings");
          g.writeString(Channel.ENCODING);
          g.writeEndArray();
          g.writeObjectFieldStart("metadata");
          for (var e : metadata.entrySet()) {
            g.writeStringField(e.getKey(), e.getValue());
          }
          g.writeEndObject();
          g.writeStringField("sessionId", sessionId);
          g.writeEndObject();
        });
  }

  /** Advertises {@code channels}. */
  public static String advertise(List<Channel> channels) {
    return Json.string(
        g -> {
          g.writeStartObject();
          g.writeStringField("op", "advertise");
          g.writeArrayFieldStart("channels");
          for (Channel c : channels) {
            g.writeStartObject();
            g.writeNumberField("id", c.id());
            g.writeStringField("topic", c.topic());
            g.writeStringField("encoding", Channel.ENCODING);
            g.writeStringField("schemaName", c.kind().schemaName());
            g.writeStringField("schema", c.kind().schema());
            g.writeStringField("schemaEncoding", Channel.SCHEMA_ENCODING);
            g.writeEndObject();
          }
          g.writeEndArray();
          g.writeEndObject();
        });
  }

  /** Withdraws channels. */
  public static String unadvertise(List<Channel> channels) {
    return Json.string(
        g -> {
          g.writeStartObject();
          g.writeStringField("op", "unadvertise");
          g.writeArrayFieldStart("channelIds");
          for (Channel c : channels) {
            g.writeNumber(c.id());
          }
          g.writeEndArray();
          g.writeEndObject();
        });
  }

  /** A status line for the client (a refusal, a drop). */
  public static String status(Level level, String message) {
    return Json.string(
        g -> {
          g.writeStartObject();
          g.writeStringField("op", "status");
          g.writeNumberField("level", level.ordinal());
          g.writeStringField("message", message);
          g.writeEndObject();
        });
  }

  /** Message data: opcode, subscription id (uint32 LE), time stamp (uint64 LE ns), payload. */
  public static ByteBuffer messageData(int subscriptionId, long timeNanos, byte[] payload) {
    ByteBuffer b = ByteBuffer.allocate(13 + payload.length).order(ByteOrder.LITTLE_ENDIAN);
    b.put(MESSAGE_DATA).putInt(subscriptionId).putLong(timeNanos).put(payload);
    return b.flip();
  }

  /** The server's time: opcode, time stamp (uint64 LE ns). */
  public static ByteBuffer time(long timeNanos) {
    ByteBuffer b = ByteBuffer.allocate(9).order(ByteOrder.LITTLE_ENDIAN);
    b.put(TIME).putLong(timeNanos);
    return b.flip();
  }
}
