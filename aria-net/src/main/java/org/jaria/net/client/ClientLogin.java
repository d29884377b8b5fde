package org.jaria.net.client;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.protocol.LoginDigest;
import org.jaria.net.protocol.Protocol;

/**
 * A client's side of ArNetworking's login: read the server's introduction, answer with the user
 * name and the digest of server key, password key and password, ask for TCP only, then read the
 * data list until its three parts are complete (or a rejection). Also reads one framed packet, for
 * the login and for the client's reader thread.
 */
final class ClientLogin {

  private ClientLogin() {}

  /**
   * Logs in on an open connection and fills {@code list}.
   *
   * @throws ArClientException if the server rejects the login or does not introduce itself; the
   *     message says why
   */
  static void login(
      DataInputStream in,
      OutputStream o,
      String user,
      String password,
      String serverKey,
      DataList list)
      throws IOException, ArClientException {
    ArNetPacket intro = readPacket(in);
    if (intro.getCommand() != Protocol.SERVER_INTRODUCTION) {
      throw new ArClientException(
          "the server did not introduce itself (got command " + intro.getCommand() + ")");
    }
    intro.bufToStr(); // version
    intro.bufToUByte2(); // its UDP port: we use TCP only
    intro.bufToUByte4(); // auth key, for UDP
    intro.bufToUByte4(); // intro key, for UDP
    String passwordKey = intro.bufToStr();
    ArNetPacket reply = new ArNetPacket(Protocol.CLIENT_INTRODUCTION);
    reply
        .uByte2ToBuf(0)
        .strToBuf(user)
        .dataToBuf(LoginDigest.digest(serverKey, passwordKey, password))
        .strToBuf(Protocol.JARIA_ACK_VERSION)
        .byteToBuf(0);
    o.write(reply.toWire());
    o.write(new ArNetPacket(Protocol.CLIENT_TCP_ONLY).toWire());
    o.flush();
    int listed = -1;
    int argRet = 0;
    int groups = 0;
    while (listed < 0 || argRet < listed || groups < listed) {
      ArNetPacket p = readPacket(in);
      switch (p.getCommand()) {
        case Protocol.SERVER_REJECTED -> {
          int reason = p.bufToByte2();
          String text = p.hasMore() ? p.bufToStr() : "";
          throw new ArClientException(rejection(reason, text));
        }
        case Protocol.SERVER_SHUTDOWN ->
            throw new ArClientException("the server closed the connection at login");
        case Protocol.SERVER_LIST -> listed = Math.max(listed, 0) + list.add(p);
        case Protocol.SERVER_LIST_ARGRET -> argRet += list.add(p);
        case Protocol.SERVER_LIST_GROUP_AND_FLAGS -> groups += list.add(p);
        default -> {
          // CONNECTED, TCP_ONLY, UDP_CONFIRMATION: nothing to do.
        }
      }
    }
  }

  /** What a REJECTED reason means, for people. */
  static String rejection(int reason, String text) {
    String why =
        switch (reason) {
          case Protocol.REJECTED_BAD_LOGIN -> "login refused: wrong user name or password";
          case Protocol.REJECTED_CENTRAL_SERVER ->
              "the robot is served by a central server at " + text;
          case Protocol.REJECTED_SERVER_PROTOCOL -> "the server wants another protocol version";
          case Protocol.REJECTED_TOO_MANY_CLIENTS -> "the server has its maximum of clients";
          case Protocol.REJECTED_WRONG_TYPE -> "the server wants another type of client";
          default -> "rejected (reason " + reason + ")";
        };
    return text.isEmpty() || reason == Protocol.REJECTED_CENTRAL_SERVER ? why : why + ": " + text;
  }

  /** Reads one framed packet; throws {@link ArNetPacketException} if the bytes are not one. */
  static ArNetPacket readPacket(DataInputStream in) throws IOException {
    int s1 = in.readUnsignedByte();
    int s2 = in.readUnsignedByte();
    if (s1 != ArNetPacket.SYNC1 || s2 != ArNetPacket.SYNC2) {
      throw new ArNetPacketException(
          String.format("a packet starts with %02x %02x, not 0f 0c", s1, s2));
    }
    int lo = in.readUnsignedByte();
    int hi = in.readUnsignedByte();
    int len = lo | hi << 8;
    if (len < ArNetPacket.HEADER_LENGTH + ArNetPacket.FOOTER_LENGTH
        || len > ArNetPacket.MAX_LENGTH) {
      throw new ArNetPacketException("a packet announced " + len + " bytes");
    }
    byte[] w = new byte[len];
    w[0] = (byte) s1;
    w[1] = (byte) s2;
    w[2] = (byte) lo;
    w[3] = (byte) hi;
    in.readFully(w, 4, len - 4);
    return ArNetPacket.fromWire(w, 0, len);
  }
}
