package org.jaria.web.server;

import org.jaria.web.foxglove.Channel;
import org.jaria.web.foxglove.Message;

/**
 * Takes every message the server publishes, on every channel (a recording). Called on the
 * publisher's thread, in order; it must not block for long.
 */
public interface MessageSink extends AutoCloseable {

  /** A message on {@code channel} (the channel is new the first time it is seen). */
  void write(Channel channel, Message message);

  /** Ends the sink (closes a file). */
  @Override
  void close();
}
