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

  /** The data the LIST packets among {@code packets} name: command number to name. */
  public static java.util.Map<Integer, String> listedCommands(List<ArNetPacket> packets) {
    java.util.Map<Integer, String> names = new java.util.LinkedHashMap<>();
    for (ArNetPacket p : packets) {
      if (p.getCommand() == org.jaria.net.protocol.Protocol.SERVER_LIST) {
        ArNetPacket r = p.toReader();
        int n = r.bufToUByte2();
        for (int k = 0; k < n; k++) {
          int cmd = r.bufToUByte2();
          names.put(cmd, r.bufToStr());
          r.bufToStr();
        }
      }
    }
    return names;
  }

  /**
   * The client's recorded packets {@code c2s} with each data number (as a command, or in a REQUEST
   * or REQUEST_STOP) changed from what the recorded server listed ({@code s2c}) to what {@code
   * numberOf} gives for the same name now. ArNetworking numbers data in the order a server
   * registers them, so a recording stays valid when services are added to the server.
   */
  public static byte[] renumbered(
      byte[] c2s, byte[] s2c, java.util.function.ToIntFunction<String> numberOf) {
    java.util.Map<Integer, String> then = listedCommands(packets(s2c));
    java.util.function.IntUnaryOperator now =
        cmd -> {
          String name = then.get(cmd);
          if (name == null) {
            throw new IllegalStateException("data " + cmd + " was not listed in the recording");
          }
          int n = numberOf.applyAsInt(name);
          if (n <= 0) {
            throw new IllegalStateException("the server has no data '" + name + "' now");
          }
          return n;
        };
    java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
    for (ArNetPacket p : packets(c2s)) {
      int cmd = p.getCommand();
      byte[] body = p.toByteArray();
      if (cmd >= org.jaria.net.protocol.Protocol.FIRST_DATA_COMMAND) {
        cmd = now.applyAsInt(cmd);
      } else if ((cmd == org.jaria.net.protocol.Protocol.CLIENT_REQUEST
              || cmd == org.jaria.net.protocol.Protocol.CLIENT_REQUEST_STOP)
          && body.length >= 2) {
        int data = now.applyAsInt((body[0] & 0xff) | (body[1] & 0xff) << 8);
        body[0] = (byte) data;
        body[1] = (byte) (data >> 8);
      }
      ArNetPacket q = new ArNetPacket(cmd);
      q.dataToBuf(body);
      out.writeBytes(q.toWire());
    }
    return out.toByteArray();
  }
}
