package org.jaria.web.foxglove;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.jaria.web.json.JsonValues;

/**
 * Reads what a client sends: JSON text operations and binary client-publish messages. Never throws:
 * anything that is not a message of the protocol becomes {@link ClientRequest.Malformed} (with what
 * is wrong) or {@link ClientRequest.Unknown} (a well-formed but unsupported operation).
 */
public final class ClientMessages {

  /** Most entries one subscribe, unsubscribe, advertise or unadvertise may list. */
  public static final int MAX_ENTRIES = 256;

  /** Binary opcode of a client's message data. */
  public static final int CLIENT_MESSAGE_DATA = 1;

  private ClientMessages() {}

  /** Reads a text message. */
  public static ClientRequest parse(String text) {
    Object v;
    try {
      v = JsonValues.read(text);
    } catch (JsonValues.BadJson e) {
      return new ClientRequest.Malformed(e.getMessage());
    }
    if (!(v instanceof Map<?, ?> m)) {
      return new ClientRequest.Malformed("a message is a JSON object");
    }
    if (!(m.get("op") instanceof String op)) {
      return new ClientRequest.Malformed("a message needs an \"op\" string");
    }
    try {
      return switch (op) {
        case "subscribe" -> subscribe(m);
        case "unsubscribe" -> new ClientRequest.Unsubscribe(ids(m, "subscriptionIds"));
        case "advertise" -> advertise(m);
        case "unadvertise" -> new ClientRequest.Unadvertise(ids(m, "channelIds"));
        default -> new ClientRequest.Unknown(op.length() > 64 ? op.substring(0, 64) : op);
      };
    } catch (IllegalArgumentException e) {
      return new ClientRequest.Malformed(op + ": " + e.getMessage());
    }
  }

  /** Reads a binary message: opcode 1, channel id (uint32 LE), payload. */
  public static ClientRequest parse(ByteBuffer data) {
    ByteBuffer b = data.duplicate().order(ByteOrder.LITTLE_ENDIAN);
    if (b.remaining() < 5) {
      return new ClientRequest.Malformed(
          "a binary message has an opcode and a channel id (5 bytes), got " + b.remaining());
    }
    int opcode = b.get() & 0xFF;
    if (opcode != CLIENT_MESSAGE_DATA) {
      return new ClientRequest.Unknown("binary opcode " + opcode);
    }
    long channel = b.getInt() & 0xFFFFFFFFL;
    byte[] payload = new byte[b.remaining()];
    b.get(payload);
    return new ClientRequest.Publish(channel, payload);
  }

  private static ClientRequest subscribe(Map<?, ?> m) {
    List<ClientRequest.Subscription> subs = new ArrayList<>();
    for (Object o : list(m, "subscriptions")) {
      if (!(o instanceof Map<?, ?> s)) {
        throw new IllegalArgumentException("each subscription is an object");
      }
      subs.add(new ClientRequest.Subscription(id(s, "id"), id(s, "channelId")));
    }
    return new ClientRequest.Subscribe(subs);
  }

  private static ClientRequest advertise(Map<?, ?> m) {
    List<ClientRequest.ClientChannel> channels = new ArrayList<>();
    for (Object o : list(m, "channels")) {
      if (!(o instanceof Map<?, ?> c)) {
        throw new IllegalArgumentException("each channel is an object");
      }
      channels.add(
          new ClientRequest.ClientChannel(
              id(c, "id"), string(c, "topic"), string(c, "encoding"), optString(c, "schemaName")));
    }
    return new ClientRequest.Advertise(channels);
  }

  private static List<?> list(Map<?, ?> m, String field) {
    if (!(m.get(field) instanceof List<?> l)) {
      throw new IllegalArgumentException("\"" + field + "\" must be a list");
    }
    if (l.size() > MAX_ENTRIES) {
      throw new IllegalArgumentException(
          "\"" + field + "\" lists " + l.size() + " entries; at most " + MAX_ENTRIES);
    }
    return l;
  }

  private static List<Long> ids(Map<?, ?> m, String field) {
    List<Long> out = new ArrayList<>();
    for (Object o : list(m, field)) {
      out.add(asId(o, field));
    }
    return out;
  }

  private static long id(Map<?, ?> m, String field) {
    return asId(m.get(field), field);
  }

  private static long asId(Object o, String field) {
    if (o instanceof Long l && l >= 0 && l <= 0xFFFFFFFFL) {
      return l;
    }
    throw new IllegalArgumentException("\"" + field + "\" must be a whole number 0..2^32-1");
  }

  private static String string(Map<?, ?> m, String field) {
    if (m.get(field) instanceof String s) {
      return s;
    }
    throw new IllegalArgumentException("\"" + field + "\" must be a string");
  }

  private static String optString(Map<?, ?> m, String field) {
    return m.get(field) instanceof String s ? s : "";
  }
}
