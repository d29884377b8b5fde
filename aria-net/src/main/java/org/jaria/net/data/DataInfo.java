package org.jaria.net.data;

import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;
import org.jaria.net.protocol.Protocol;

/**
 * One entry of a server's data list, sent at login (ArNetworking's data list): what a client may
 * ask for and how.
 *
 * @param id the number used on the wire
 * @param name the name clients use ("update", "getMap", "ratioDrive" ...)
 * @param description what it is
 * @param argumentDescription the arguments, in order ("none" if none)
 * @param returnDescription the reply, in order
 * @param commandGroup the group a user needs ("" for anybody)
 * @param subscribable whether it can be subscribed to at a rate (published data)
 */
public record DataInfo(
    int id,
    String name,
    String description,
    String argumentDescription,
    String returnDescription,
    String commandGroup,
    boolean subscribable)
    implements NetEncodable {

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(7)
        .intToBuf(id)
        .strToBuf(name)
        .strToBuf(description)
        .strToBuf(argumentDescription)
        .strToBuf(returnDescription)
        .strToBuf(commandGroup)
        .intToBuf(subscribable ? Protocol.FLAG_SUBSCRIBABLE : 0);
  }

  /** Reads an entry written by {@link #write}; extra trailing fields are skipped. */
  public static DataInfo read(ArNetPacket in) {
    int n = in.bufToArray();
    if (n < 7) {
      throw new org.jaria.net.ArNetPacketException("a data list entry needs 7 fields, has " + n);
    }
    DataInfo d =
        new DataInfo(
            in.bufToInt(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            (in.bufToLong() & Protocol.FLAG_SUBSCRIBABLE) != 0);
    for (int i = 7; i < n; i++) {
      in.skip();
    }
    return d;
  }
}
