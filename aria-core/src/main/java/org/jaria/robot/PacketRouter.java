package org.jaria.robot;

import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.protocol.ArRobotPacket;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Hands each packet the link delivers to the packet handlers, in order; the first handler that
 * accepts a packet takes it (ARIA's packet handler list). Handlers may be added and removed from
 * any thread; packets are routed on the thread that runs the cycle (or connects), holding the
 * robot's lock.
 */
final class PacketRouter {

  private static final Logger log = LoggerFactory.getLogger(PacketRouter.class);

  private final CopyOnWriteArrayList<ArPacketHandler> handlers = new CopyOnWriteArrayList<>();

  /** Adds a handler at the front (asked first) or the end of the list. */
  void add(ArPacketHandler h, ArListPos pos) {
    if (pos == ArListPos.FIRST) {
      handlers.add(0, h);
    } else {
      handlers.add(h);
    }
  }

  /** Removes a handler. */
  void remove(ArPacketHandler h) {
    handlers.remove(h);
  }

  /** Offers {@code p} to the handlers in order until one accepts it. */
  void route(ArRobotPacket p) {
    for (ArPacketHandler h : handlers) {
      p.resetRead();
      if (h.handle(p)) {
        return;
      }
    }
    log.debug("no packet handler wanted packet 0x{}", Integer.toHexString(p.getID()));
  }
}
