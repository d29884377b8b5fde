package org.jaria.net.server.info;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.MapBinaryLayout;
import org.jaria.net.data.MapData;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.Where;

/**
 * The robot's map for clients (ArNetworking's {@code ArServerHandlerMap}), with ArNetworking's
 * names and layouts: {@code "getMapName"} answers the map's file name; {@code "getMap"} sends the
 * map's .map text one line per packet, then a packet with an empty string, then an empty packet;
 * {@code "mapUpdated"} is an empty packet sent to the clients that requested it (with interval -1)
 * whenever {@link #setMap} changes the map.
 */
public final class ArServerHandlerMap {

  private final ArServerBase server;
  private volatile MapData current;

  /**
   * Registers the map data with {@code server}.
   *
   * @param arMap the map (null for none yet); it is rendered now, so it may be changed afterwards
   * @param name the map's name, usually its file name
   */
  public ArServerHandlerMap(ArServerBase server, ArMap arMap, String name) {
    this.server = server;
    server.addData(
        "getMapName",
        "gets the name of the map being used",
        "none",
        "string: map name (empty string if no maps)",
        "Map",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {
          MapData m = current;
          reply.strToBuf(m == null ? "" : m.name());
        });
    server.addData(
        "getMap",
        "gets the map as a set of ascii lines",
        "none",
        "packets of '<string>: line' followed by a packet with an empty string to denote end (if"
            + " only empty string then no map)",
        "Map",
        "RETURN_UNTIL_EMPTY",
        Where.WORKER,
        (client, request, reply) -> {
          int cmd = server.findCommandFromName("getMap");
          MapData m = current;
          if (m != null) {
            for (String line : m.text().split("\n", -1)) {
              if (line.isEmpty()) {
                continue; // an empty line would end the map early
              }
              ArNetPacket p = new ArNetPacket(cmd);
              p.strToBuf(line.length() > 4000 ? line.substring(0, 4000) : line);
              client.sendPacketTcp(p);
            }
          }
          ArNetPacket end = new ArNetPacket(cmd);
          end.strToBuf("");
          client.sendPacketTcp(end);
          // The (empty) reply packet the server sends next ends the answer.
        });
    server.addData(
        "mapUpdated",
        "a single packet is sent to this when the map is updated and this denotes a new getMap"
            + " and getMapName should be requested",
        "none",
        "none",
        "Map",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {});
    if (arMap != null) {
      setMap(arMap, name);
    }
  }

  /**
   * Registers {@code "getMapBinary"} (the map with its lines and points as numbers, {@link
   * MapBinaryLayout}); separate from the constructor so a server can add it after its other data.
   */
  public void addMapBinary() {
    server.addData(
        "getMapBinary",
        "gets the map objects as ascii and the data points as binary",
        "none",
        "packets of '<string>: line' for header, followed by packets of '<byte4>: numPtsInPacket,"
            + " (<double>:x, <double>:y)*' until numPtsInPacket == 0",
        "Map",
        "RETURN_UNTIL_EMPTY",
        Where.WORKER,
        (client, request, reply) -> {
          int cmd = server.findCommandFromName("getMapBinary");
          MapData m = current;
          if (m == null) {
            ArNetPacket none = new ArNetPacket(cmd);
            none.strToBuf("");
            client.sendPacketTcp(none);
            return;
          }
          for (ArNetPacket p : MapBinaryLayout.bodies(m.text())) {
            p.setCommand(cmd);
            client.sendPacketTcp(p);
          }
          // The (empty) reply packet the server sends next ends the answer.
        });
  }

  /**
   * Serves a new map (from any thread; the map is rendered to text now, so keep it unchanged during
   * this call) and tells the clients that asked for mapUpdated.
   */
  public synchronized void setMap(ArMap arMap, String name) {
    StringWriter w = new StringWriter();
    try {
      arMap.write(w);
    } catch (IOException e) {
      throw new UncheckedIOException("writing a map to a string cannot fail", e);
    }
    MapData old = current;
    current = new MapData(name, old == null ? 1 : old.version() + 1, w.toString());
    if (old != null) {
      server.broadcastPacketTcp(new ArNetPacket(), "mapUpdated");
    }
  }

  /** The map being served, or null. */
  public MapData getMapData() {
    return current;
  }
}
