package org.jaria.net.data;

import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * Helpers for the records' encodings: each record is one array of fields; readers need at least the
 * fields they know and skip any that a newer server appended (so the protocol can grow without
 * breaking old clients).
 */
final class Fields {

  private Fields() {}

  /** Reads an array header and checks it has at least {@code known} fields. */
  static int begin(ArNetPacket in, int known, String what) {
    int n = in.bufToArray();
    if (n < known) {
      throw new ArNetPacketException(what + " needs " + known + " fields, has " + n);
    }
    return n;
  }

  /** Skips the fields after the {@code known} ones. */
  static void end(ArNetPacket in, int n, int known) {
    if (n != known) {
      throw new ArNetPacketException("expected " + known + " fields, got " + n);
    }
  }

  static void writePose(ArNetPacket out, ArPose p) {
    if (p == null) {
      out.uByteToBuf(0);
    } else {
      out.uByteToBuf(1).doubleToBuf(p.getX()).doubleToBuf(p.getY()).doubleToBuf(p.getTh());
    }
  }

  static ArPose readPose(ArNetPacket in) {
    if (in.bufToUByte() == 0) {
      return null;
    }
    return new ArPose(in.bufToDouble(), in.bufToDouble(), in.bufToDouble());
  }
}
