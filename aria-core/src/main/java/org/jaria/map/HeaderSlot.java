package org.jaria.map;

/**
 * One line of a map's header, kept as read so that an unedited line is written back unchanged.
 * Object lines also hold the parsed object; an edited object line has no raw text any more and is
 * written from the object.
 */
final class HeaderSlot {

  /** The keyword before ':' ("Cairn", "MinPos", ...), or "" for a line without one. */
  final String key;

  /** The line as read (without its line end), or null if it must be regenerated. */
  String raw;

  /** The object of a {@code Cairn:} line, else null. */
  ArMapObject object;

  HeaderSlot(String key, String raw, ArMapObject object) {
    this.key = key;
    this.raw = raw;
    this.object = object;
  }
}
