package org.jaria.net.data;

import java.io.IOException;
import java.io.StringReader;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * The robot's map ({@code "getMap"}): its name and its {@code .map} text, byte for byte as ArMap
 * writes it, so a client gets exactly the server's map. Large maps travel in several frames; the
 * client library puts them back together.
 *
 * @param name the map's name (its file name)
 * @param version changes whenever the server's map changes
 * @param text the {@code .map} file's text
 */
public record MapData(String name, long version, String text) implements NetEncodable {

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(3).strToBuf(name).intToBuf(version).strToBuf(text);
  }

  /** Reads what {@link #write} wrote. */
  public static MapData read(ArNetPacket in) {
    int n = Fields.begin(in, 3, "a map");
    MapData m = new MapData(in.bufToStr(), in.bufToLong(), in.bufToStr());
    Fields.end(in, n, 3);
    return m;
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
