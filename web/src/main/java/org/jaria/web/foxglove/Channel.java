package org.jaria.web.foxglove;

import java.util.Objects;

/**
 * A channel as the server advertises it: a topic with an id, JSON encoding and a JSON schema.
 *
 * @param id the channel's id, unique for the server's lifetime
 * @param topic the topic
 * @param kind what it carries (its schema)
 */
public record Channel(int id, String topic, TopicKind kind) {

  /** The message encoding of every channel of this server. */
  public static final String ENCODING = "json";

  /** The schema encoding of every channel of this server. */
  public static final String SCHEMA_ENCODING = "jsonschema";

  /** Checks. */
  public Channel {
    Objects.requireNonNull(topic, "topic");
    Objects.requireNonNull(kind, "kind");
  }
}
