package org.jaria.net;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

/**
 * Bytes recorded by hand between ARIA 2.9.1's ArNetworking programs and JAria (see
 * docs/networking.md, "Proof by hand"): {@code NAME.c2s.bin} is what the client sent, {@code
 * NAME.s2c.bin} what the server sent, each exactly as it crossed the socket.
 */
public final class PeerRecording {

  private PeerRecording() {}

  /** The bytes of resource {@code peers/NAME}. */
  public static byte[] bytes(String name) {
    try (InputStream in = PeerRecording.class.getResourceAsStream("peers/" + name)) {
      if (in == null) {
        throw new IllegalStateException("no recording peers/" + name);
      }
      return in.readAllBytes();
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  /** The packets in {@code wire}, in order (each checked: sync, length, checksum). */
  public static List<ArNetPacket> packets(byte[] wire) {
    List<ArNetPacket> l = new ArrayList<>();
    int i = 0;
    while (i < wire.length) {
      int len = (wire[i + 2] & 0xff) | (wire[i + 3] & 0xff) << 8;
      l.add(ArNetPacket.fromWire(wire, i, len));
      i += len;
    }
    return l;
  }

  /** The whole wire bytes of the packets from index {@code from} on. */
  public static byte[] from(byte[] wire, int from) {
    int i = 0;
    for (int k = 0; k < from; k++) {
      i += (wire[i + 2] & 0xff) | (wire[i + 3] & 0xff) << 8;
    }
    return java.util.Arrays.copyOfRange(wire, i, wire.length);
  }

  /** The data names of the LIST packets among {@code packets}. */
  public static List<String> listedNames(List<ArNetPacket> packets) {
    List<String> names = new ArrayList<>();
    for (ArNetPacket p : packets) {
      if (p.getCommand() == org.jaria.net.protocol.Protocol.SERVER_LIST) {
        ArNetPacket r = p.toReader();
        int n = r.bufToUByte2();
        for (int k = 0; k < n; k++) {
          r.bufToUByte2();
          names.add(r.bufToStr());
          r.bufToStr();
        }
      }
    }
    return names;
  }
}
