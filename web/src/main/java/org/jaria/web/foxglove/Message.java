package org.jaria.web.foxglove;

import java.util.Objects;

/**
 * One encoded message on a topic: what every subscriber of the topic and the recording get. The
 * payload is encoded once per frame and shared; nobody changes it after it is made.
 *
 * @param topic the topic ({@code /robot1/laser})
 * @param kind what it carries
 * @param timeNanos its time stamp (the source's clock)
 * @param payload the JSON, UTF-8
 */
// The payload array is shared read-only between the subscribers: copying it for each one is what
// encoding once avoids.
@SuppressWarnings("ArrayRecordComponent")
public record Message(String topic, TopicKind kind, long timeNanos, byte[] payload) {

  /** Checks. */
  public Message {
    Objects.requireNonNull(topic, "topic");
    Objects.requireNonNull(kind, "kind");
    Objects.requireNonNull(payload, "payload");
  }

  /** The payload as text (for tests and logs). */
  public String json() {
    return new String(payload, java.nio.charset.StandardCharsets.UTF_8);
  }
}
