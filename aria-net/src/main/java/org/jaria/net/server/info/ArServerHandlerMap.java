package org.jaria.net.server.info;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import org.jaria.map.ArMap;
import org.jaria.net.data.MapData;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PublishedValue;
import org.jaria.net.server.Where;

/**
 * The robot's map for clients (ArNetworking's {@code ArServerHandlerMap}): {@code "getMap"} sends
 * the {@code .map} text (in several frames when large; rendered once per map, shared by every
 * client), {@code "getMapName"} its name and version. Subscribing to {@code "getMap"} at a slow
 * rate delivers the map once and again whenever {@link #setMap} changes it.
 */
public final class ArServerHandlerMap {

  private final PublishedValue map = new PublishedValue();
  private volatile MapData current;

  /**
   * Registers the map data with {@code server}.
   *
   * @param arMap the map (null for none yet); it is rendered now, so it may be changed afterwards
   * @param name the map's name, usually its file name
   */
  public ArServerHandlerMap(ArServerBase server, ArMap arMap, String name) {
    server.addPublishedData(
        "getMap",
        "the map as .map text; subscribe slowly to hear of new maps",
        "MapData [name, version, text]",
        "MapInfo",
        map);
    server.addData(
        "getMapName",
        "the map's name and version",
        "none",
        "string name, int version",
        "MapInfo",
        Where.WORKER,
        (client, request, reply) -> {
          MapData m = current;
          reply.strToBuf(m == null ? "" : m.name()).intToBuf(m == null ? 0 : m.version());
        });
    if (arMap != null) {
      setMap(arMap, name);
    }
  }

  /**
   * Serves a new map (from any thread; the map is rendered to text now, so keep it unchanged during
   * this call).
   */
  public synchronized void setMap(ArMap arMap, String name) {
    StringWriter w = new StringWriter();
    try {
      arMap.write(w);
    } catch (IOException e) {
      throw new UncheckedIOException("writing a map to a string cannot fail", e);
    }
    MapData old = current;
    MapData m = new MapData(name, old == null ? 1 : old.version() + 1, w.toString());
    current = m;
    map.publish(m);
  }

  /** The map being served, or null. */
  public MapData getMapData() {
    return current;
  }
}
