package org.jaria.net.data;

import java.io.IOException;
import java.io.StringReader;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.net.ArNetPacket;

/**
 * The robot's map ({@code "getMap"}): its name and its {@code .map} text, byte for byte as ArMap
 * writes it, so a client gets exactly the server's map. The map travels one line per packet
 * (ArNetworking's getMap); ArClientBase gathers them.
 *
 * @param name the map's name (its file name)
 * @param version changes whenever the server's map changes
 * @param text the {@code .map} file's text
 */
public record MapData(String name, long version, String text) {

  /**
   * Reads the answer to ArNetworking's getMap (the lines of every packet, gathered by {@code
   * ArClientBase.requestOnce}), ending at the first empty string.
   *
   * @param name the map's name (from getMapName)
   * @param version a number that changes with each new map (the client counts mapUpdated)
   */
  public static MapData read(ArNetPacket in, String name, long version) {
    StringBuilder sb = new StringBuilder();
    while (in.hasMore()) {
      String line = in.bufToStr();
      if (line.isEmpty()) {
        break;
      }
      sb.append(line).append('\n');
    }
    return new MapData(name, version, sb.toString());
  }

  /**
   * Parses the text into an {@link ArMap}.
   *
   * @throws MapFormatException if the server's map is not a well-formed map
   */
  public ArMap toArMap() throws MapFormatException {
    try {
      return ArMap.read(new StringReader(text), "server map " + name);
    } catch (IOException e) {
      throw new IllegalStateException("reading a string cannot fail", e);
    }
  }
}
