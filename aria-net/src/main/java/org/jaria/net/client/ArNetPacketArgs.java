package org.jaria.net.client;

import org.jaria.net.ArNetPacket;

/**
 * Builds request arguments from Java values, each written in the ArNetworking type its class maps
 * to.
 */
public final class ArNetPacketArgs {

  private ArNetPacketArgs() {}

  /**
   * A packet holding {@code values}: a Double or Float as a double, an Integer as a byte4, a Short
   * as a byte2, a Byte as a byte, a Long as a byte8, a Boolean as a ubyte 1/0, a String as a
   * string, a byte[] as raw bytes.
   *
   * @throws IllegalArgumentException for a value of another class
   */
  public static ArNetPacket of(Object... values) {
    ArNetPacket p = new ArNetPacket();
    for (Object v : values) {
      if (v instanceof Double || v instanceof Float) {
        p.doubleToBuf(((Number) v).doubleValue());
      } else if (v instanceof Integer i) {
        p.byte4ToBuf(i);
      } else if (v instanceof Short s) {
        p.byte2ToBuf(s);
      } else if (v instanceof Byte b) {
        p.byteToBuf(b);
      } else if (v instanceof Long l) {
        p.byte8ToBuf(l);
      } else if (v instanceof Boolean b) {
        p.boolToBuf(b);
      } else if (v instanceof String s) {
        p.strToBuf(s);
      } else if (v instanceof byte[] b) {
        p.dataToBuf(b);
      } else if (v instanceof java.util.List<?> l) {
        // JAria's layouts for lists: a ubyte4 count, then the elements.
        p.arrayToBuf(l.size());
        p.dataToBuf(of(l.toArray()).toByteArray());
      } else {
        throw new IllegalArgumentException(
            "cannot send a "
                + (v == null ? "null" : v.getClass().getSimpleName())
                + " as an ArNetworking value; build an ArNetPacket");
      }
    }
    return p;
  }
}
