package org.jaria.web.server;

import java.util.ArrayList;
import java.util.List;
import org.jaria.web.foxglove.Channel;
import org.jaria.web.foxglove.ChannelTable;
import org.jaria.web.foxglove.FrameEncoder;
import org.jaria.web.foxglove.Message;
import org.jaria.web.foxglove.ServerMessages;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.WorldFrame;
import org.jaria.web.source.FrameSource;

/**
 * One publishing step, run by the server's publisher thread at the frame rate: takes a frame from
 * the source, encodes it once, brings the channels up to date, and hands each message to every
 * client subscribed to its channel and to the sinks. Owned by that one thread.
 */
final class Publisher {

  private final FrameSource source;
  private final WebServer hub;
  private final ChannelTable table = new ChannelTable();
  private MapLayer lastMap;
  private Message mapMessage;

  Publisher(FrameSource source, WebServer hub) {
    this.source = source;
    this.hub = hub;
  }

  /** Publishes one frame. */
  void step() {
    long sampled = System.nanoTime();
    MapLayer map = source.map();
    WorldFrame frame = source.frame();
    long t = frame.clock().timeNanos();
    hub.frameTaken(t, sampled);
    boolean mapChanged = !java.util.Objects.equals(map, lastMap);
    if (mapChanged) {
      lastMap = map;
      mapMessage = FrameEncoder.encodeMap(map, t);
    }
    List<Message> messages = new ArrayList<>(FrameEncoder.encode(frame));
    messages.add(0, mapMessage);
    ChannelTable.Change change = table.update(messages);
    if (!change.isEmpty() || mapChanged) {
      hub.channelsChanged(table.all(), change, mapChanged ? mapMessage : null);
    }
    List<ClientConnection> clients = hub.clientList();
    List<MessageSink> sinks = hub.sinkList();
    for (int i = mapChanged ? 0 : 1; i < messages.size(); i++) {
      // The map (first) is sent when it changes, and to each new subscriber.
      Message m = messages.get(i);
      Channel c = table.get(m.topic());
      for (ClientConnection client : clients) {
        long sub = client.state().subscriptionFor(c.id());
        if (sub >= 0) {
          client.send(ServerMessages.messageData((int) sub, m.timeNanos(), m.payload()));
        }
      }
      for (MessageSink s : sinks) {
        s.write(c, m);
      }
    }
    hub.counters().frames.increment();
  }
}
