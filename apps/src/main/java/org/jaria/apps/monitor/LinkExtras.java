package org.jaria.apps.monitor;

import java.time.Duration;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.DrawingLayout;
import org.jaria.net.data.LocState;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.NamedDrawing;
import org.jaria.net.data.PathPoints;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.Points;
import org.jaria.net.data.PopupLayout;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The parts of the monitor's link that depend on what the server offers, chosen after the login:
 * the localization and the path (JAria's snapshots from a JAria server, ARNL's layouts from
 * another), the server's drawings (ArServerInfoDrawings, each asked for at its refresh time) and
 * its popups (ArServerHandlerPopup).
 */
final class LinkExtras {

  private static final Logger log = LoggerFactory.getLogger(LinkExtras.class);

  /** The fastest a drawing is asked for, ms (ArNetworking's default refresh is 200 ms). */
  static final long MIN_DRAWING_MS = 100;

  private final ArClientBase client;
  private final MonitorState state;
  private final Runnable changed;
  private final java.util.Set<String> handled = java.util.concurrent.ConcurrentHashMap.newKeySet();

  LinkExtras(ArClientBase client, MonitorState state, Runnable changed) {
    this.client = client;
    this.state = state;
    this.changed = changed;
    handle(
        "getLocState",
        p -> {
          if (!client.dataExists("getLocalizationSnapshot")) {
            LocState s = LocState.read(p);
            state.localization =
                new LocalizationSnapshot(s.stateName(), s.score() / 100.0, null, 0, false);
            changed.run();
          }
        });
    handle(
        "getPath",
        p -> {
          if (!client.dataExists("getPathSnapshot")) {
            state.path = new PathSnapshot("", "", null, PathPoints.read(p).path(), Points.EMPTY);
            changed.run();
          }
        });
    handle(
        "popupCreate",
        p -> {
          PopupLayout.Shown s = PopupLayout.readCreate(p);
          if (s != null) {
            Map<Integer, PopupLayout.Shown> m = new LinkedHashMap<>(state.popups);
            m.put(s.id(), s);
            state.popups = Map.copyOf(m);
            changed.run();
          }
        });
    handle(
        "popupClose",
        p -> {
          PopupLayout.Closed c = PopupLayout.readClose(p);
          Map<Integer, PopupLayout.Shown> m = new HashMap<>(state.popups);
          if (m.remove(c.id()) != null) {
            state.popups = Map.copyOf(m);
            changed.run();
          }
        });
  }

  /** Subscribes to what this server offers (after the login). */
  void connected(long mediumMs) {
    subscribe(
        client.dataExists("getLocalizationSnapshot") ? "getLocalizationSnapshot" : "getLocState",
        mediumMs);
    subscribe(client.dataExists("getPathSnapshot") ? "getPathSnapshot" : "getPath", mediumMs);
    if (client.dataExists("popupCreate")) {
      subscribe("popupCreate", -1);
      subscribe("popupClose", -1);
      if (client.dataExists("popupList")) {
        CompletableFuture<?> unused = client.requestOnce("popupList");
      }
    }
    if (client.dataExists("getDrawingList")) {
      CompletableFuture<?> unused =
          client
              .requestOnce("getDrawingList")
              .thenAccept(p -> drawings(DrawingLayout.readAllListed(p)))
              .exceptionally(
                  e -> {
                    log.info("the server's drawings could not be read: {}", e.getMessage());
                    return null;
                  });
    }
  }

  private void drawings(List<NamedDrawing> list) {
    state.drawings = List.copyOf(list);
    for (NamedDrawing d : list) {
      String name = d.name();
      if (!handled.add(name)) {
        continue; // asked again after a reconnect: the handler is there
      }
      handle(
          name,
          p -> {
            Map<String, Points> m = new HashMap<>(state.drawingPoints);
            m.put(name, DrawingLayout.readPoints(p));
            state.drawingPoints = Map.copyOf(m);
            changed.run();
          });
      long every = d.data().defaultRefreshTime();
      subscribe(name, every == 0 ? -1 : Math.max(MIN_DRAWING_MS, every));
    }
  }

  /**
   * Adds a handler that stops asking for {@code name} when its packets are not in the layout the
   * monitor reads (another server's layout of a data of the same name), rather than failing at
   * every packet.
   */
  private void handle(String name, java.util.function.Consumer<org.jaria.net.ArNetPacket> h) {
    client.addHandler(
        name,
        p -> {
          try {
            h.accept(p);
          } catch (RuntimeException e) {
            log.info(
                "{} from this server is not in a layout the monitor reads: {}",
                name,
                e.getMessage());
            client.requestStop(name);
          }
        });
  }

  /** Answers popup {@code id} with button {@code button}. */
  CompletableFuture<?> popupClicked(int id, int button) {
    return client.requestOnce("popupClicked", id, (byte) button);
  }

  private void subscribe(String name, long ms) {
    CompletableFuture<Duration> unused =
        client
            .request(name, ms)
            .exceptionally(
                e -> {
                  log.debug("no subscription to {}: {}", name, e.getMessage());
                  return null;
                });
  }
}
