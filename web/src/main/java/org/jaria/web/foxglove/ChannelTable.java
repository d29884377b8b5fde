package org.jaria.web.foxglove;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The channels the server advertises, kept in step with the topics the frames carry: a new topic (a
 * robot joins, or its laser's first scan) gets a new channel; a topic no frame carries any more
 * (the robot left) loses its channel. Ids are never reused, so a viewer's old subscription cannot
 * land on another topic. Not thread-safe: one publisher thread owns it.
 */
public final class ChannelTable {

  private final Map<String, Channel> byTopic = new LinkedHashMap<>();
  private int nextId = 1;

  /**
   * What changed.
   *
   * @param added channels to advertise
   * @param removed channels to unadvertise
   */
  public record Change(List<Channel> added, List<Channel> removed) {
    /** Copies. */
    public Change {
      added = List.copyOf(added);
      removed = List.copyOf(removed);
    }

    /** Whether nothing changed. */
    public boolean isEmpty() {
      return added.isEmpty() && removed.isEmpty();
    }
  }

  /**
   * Brings the table to {@code messages}' topics: the map's topic stays once it is there; any other
   * topic stays only while a message carries it.
   */
  public Change update(List<Message> messages) {
    List<Channel> added = new ArrayList<>();
    Set<String> seen = new java.util.HashSet<>();
    for (Message m : messages) {
      seen.add(m.topic());
      if (!byTopic.containsKey(m.topic())) {
        Channel c = new Channel(nextId++, m.topic(), m.kind());
        byTopic.put(m.topic(), c);
        added.add(c);
      }
    }
    List<Channel> removed = new ArrayList<>();
    for (var it = byTopic.values().iterator(); it.hasNext(); ) {
      Channel c = it.next();
      if (c.kind() != TopicKind.MAP && !seen.contains(c.topic())) {
        removed.add(c);
        it.remove();
      }
    }
    return new Change(added, removed);
  }

  /** The channel of {@code topic}, or null. */
  public Channel get(String topic) {
    return byTopic.get(topic);
  }

  /** Every channel, in the order they were made. */
  public List<Channel> all() {
    return List.copyOf(byTopic.values());
  }
}
