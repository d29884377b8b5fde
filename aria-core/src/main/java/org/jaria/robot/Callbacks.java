package org.jaria.robot;

import java.util.concurrent.CopyOnWriteArrayList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A list of callbacks for one robot event (connected, disconnected ...). Callbacks may be added and
 * removed from any thread; one that throws is logged and the others still run.
 */
final class Callbacks {

  private static final Logger log = LoggerFactory.getLogger(Callbacks.class);

  private final String event;
  private final CopyOnWriteArrayList<Runnable> list = new CopyOnWriteArrayList<>();

  Callbacks(String event) {
    this.event = event;
  }

  void add(Runnable cb) {
    list.add(cb);
  }

  void remove(Runnable cb) {
    list.remove(cb);
  }

  void invokeAll() {
    for (Runnable cb : list) {
      try {
        cb.run();
      } catch (RuntimeException e) {
        log.error("a '{}' callback threw; the other callbacks still run", event, e);
      }
    }
  }
}
