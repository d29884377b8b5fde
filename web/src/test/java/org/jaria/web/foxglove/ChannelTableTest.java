package org.jaria.web.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Channels follow the topics the frames carry; ids are never reused. */
class ChannelTableTest {

  static Message m(String topic, TopicKind k) {
    return new Message(topic, k, 0, new byte[0]);
  }

  @Test
  void newTopicsGetChannelsAndVanishedOnesLoseThem() {
    ChannelTable t = new ChannelTable();
    ChannelTable.Change c1 =
        t.update(List.of(m("/map", TopicKind.MAP), m("/a/status", TopicKind.STATUS)));
    assertEquals(List.of(1, 2), c1.added().stream().map(Channel::id).toList());
    assertTrue(
        t.update(List.of(m("/map", TopicKind.MAP), m("/a/status", TopicKind.STATUS))).isEmpty());
    ChannelTable.Change c2 = t.update(List.of(m("/b/status", TopicKind.STATUS)));
    assertEquals(List.of("/b/status"), c2.added().stream().map(Channel::topic).toList());
    assertEquals(List.of("/a/status"), c2.removed().stream().map(Channel::topic).toList());
    assertEquals(3, t.get("/b/status").id());
    assertEquals(1, t.get("/map").id(), "the map's channel stays");
    ChannelTable.Change c3 = t.update(List.of(m("/a/status", TopicKind.STATUS)));
    assertEquals(4, c3.added().get(0).id(), "a topic that comes back gets a new id");
  }
}
