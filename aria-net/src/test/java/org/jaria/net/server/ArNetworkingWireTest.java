package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.protocol.LoginDigest;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/**
 * Replays, byte for byte, what ARIA 2.9.1's clients (clientCommandLister, robotUpdateExample) send
 * to a server, and checks what a JAria server answers: the introduction, the login digest, the data
 * list, a request once and a request at an interval. See docs/networking.md.
 */
class ArNetworkingWireTest {

  private static ArNetPacket read(DataInputStream in) throws IOException {
    byte[] h = new byte[4];
    in.readFully(h);
    int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
    byte[] w = new byte[len];
    System.arraycopy(h, 0, w, 0, 4);
    in.readFully(w, 4, len - 4);
    return ArNetPacket.fromWire(w, 0, len);
  }

  private static ArNetPacket readUntil(DataInputStream in, int command) throws IOException {
    while (true) {
      ArNetPacket p = read(in);
      if (p.getCommand() == command) {
        return p;
      }
    }
  }

  private static ArServerBase server(Authenticator auth) throws IOException {
    ArServerBase s =
        new ArServerBase(ServerOptions.builder().port(0).udp(false).authenticator(auth).build());
    s.addData(
        "echo",
        "answers its string argument",
        "string: text",
        "string: text",
        "",
        Where.WORKER,
        (c, req, rep) -> rep.strToBuf(req.bufToStr()));
    s.open();
    return s;
  }

  /** ARIA's client introduction: udp port, user, digest, protocol version, type. */
  private static byte[] intro(String user, byte[] digest) {
    ArNetPacket p = new ArNetPacket(Protocol.CLIENT_INTRODUCTION);
    p.uByte2ToBuf(0).strToBuf(user).dataToBuf(digest).strToBuf("").byteToBuf(0);
    return p.toWire();
  }

  @Test
  void anAriaClientLogsInListsAndRequests() throws Exception {
    try (ArServerBase s = server(Authenticator.open());
        Socket sock = new Socket(InetAddress.getLoopbackAddress(), s.getPort())) {
      DataInputStream in = new DataInputStream(sock.getInputStream());
      OutputStream out = sock.getOutputStream();
      ArNetPacket hello = read(in);
      assertEquals(Protocol.SERVER_INTRODUCTION, hello.getCommand());
      assertEquals("alpha", hello.bufToStr());
      assertEquals(0, hello.bufToUByte2()); // no UDP port: TCP only
      out.write(intro("", new byte[16]));
      out.write(new ArNetPacket(Protocol.CLIENT_TCP_ONLY).toWire());
      assertEquals(Protocol.SERVER_CONNECTED, read(in).getCommand());
      ArNetPacket list = read(in);
      assertEquals(Protocol.SERVER_LIST, list.getCommand());
      int n = list.bufToUByte2();
      List<String> names = new ArrayList<>();
      int echo = 0;
      for (int i = 0; i < n; i++) {
        int cmd = list.bufToUByte2();
        String name = list.bufToStr();
        list.bufToStr();
        names.add(name);
        if (name.equals("echo")) {
          echo = cmd;
        }
      }
      assertEquals(List.of("requestFailed", "echo"), names);
      assertEquals(257, echo);
      assertEquals(Protocol.SERVER_LIST_ARGRET, read(in).getCommand());
      ArNetPacket flags = read(in);
      assertEquals(Protocol.SERVER_LIST_GROUP_AND_FLAGS, flags.getCommand());
      // requestOnce: the data's own command number, the arguments as the body.
      ArNetPacket once = new ArNetPacket(echo);
      once.strToBuf("hi");
      out.write(once.toWire());
      ArNetPacket reply = readUntil(in, echo);
      assertEquals("hi", reply.bufToStr());
      // request at an interval: REQUEST, byte2 command, byte4 ms, arguments.
      ArNetPacket req = new ArNetPacket(Protocol.CLIENT_REQUEST);
      req.uByte2ToBuf(echo).byte4ToBuf(50).strToBuf("again");
      out.write(req.toWire());
      assertEquals("again", readUntil(in, echo).bufToStr());
      assertEquals("again", readUntil(in, echo).bufToStr());
      ArNetPacket stop = new ArNetPacket(Protocol.CLIENT_REQUEST_STOP);
      stop.uByte2ToBuf(echo);
      out.write(stop.toWire());
      out.write(new ArNetPacket(Protocol.CLIENT_SHUTDOWN).toWire());
      assertEquals(-1, drain(in));
    }
  }

  /** Reads to the end of the stream; returns -1 when it ends. */
  private static int drain(DataInputStream in) throws IOException {
    while (in.read() >= 0) {
      // discard
    }
    return -1;
  }

  @Test
  void theLoginDigestIsMd5OfServerKeyPasswordKeyAndPassword() throws Exception {
    ArServerUserInfo users =
        ArServerUserInfo.parse(List.of("UserInfoVersion1", "user steve four RobotInfo"), "test");
    try (ArServerBase s = server(users)) {
      for (String password : List.of("five", "four")) {
        try (Socket sock = new Socket(InetAddress.getLoopbackAddress(), s.getPort())) {
          DataInputStream in = new DataInputStream(sock.getInputStream());
          ArNetPacket hello = read(in);
          hello.bufToStr();
          hello.bufToUByte2();
          hello.bufToUByte4();
          hello.bufToUByte4();
          String passwordKey = hello.bufToStr();
          sock.getOutputStream()
              .write(intro("steve", LoginDigest.digest("", passwordKey, password)));
          ArNetPacket answer = read(in);
          if (password.equals("five")) {
            assertEquals(Protocol.SERVER_REJECTED, answer.getCommand());
            assertEquals(Protocol.REJECTED_BAD_LOGIN, answer.bufToByte2());
          } else {
            assertEquals(Protocol.SERVER_CONNECTED, answer.getCommand());
            // The user's groups decide the list: "echo" is open, requestFailed too.
            assertEquals(Protocol.SERVER_LIST, read(in).getCommand());
          }
        }
      }
      assertEquals(1, s.getStats().getLoginFailed());
    }
  }

  @Test
  void repeatedLoginFailuresFromOneAddressAreThrottled() throws Exception {
    ArServerUserInfo users =
        ArServerUserInfo.parse(List.of("UserInfoVersion1", "user steve four"), "test");
    try (ArServerBase s = server(users)) {
      for (int i = 0; i < 7; i++) {
        try (Socket sock = new Socket(InetAddress.getLoopbackAddress(), s.getPort())) {
          DataInputStream in = new DataInputStream(sock.getInputStream());
          read(in);
          sock.getOutputStream().write(intro("steve", new byte[16]));
          assertEquals(Protocol.SERVER_REJECTED, read(in).getCommand());
        }
      }
      assertEquals(5, s.getStats().getLoginFailed());
      assertTrue(s.getStats().getLoginThrottled() >= 2);
    }
  }

  @Test
  void garbageInsteadOfAnIntroductionClosesOnlyThatConnection() throws Exception {
    try (ArServerBase s = server(Authenticator.open());
        Socket sock = new Socket(InetAddress.getLoopbackAddress(), s.getPort())) {
      DataInputStream in = new DataInputStream(sock.getInputStream());
      read(in);
      sock.getOutputStream().write(new byte[] {1, 2, 3, 4, 5, 6, 7, 8});
      assertEquals(-1, drain(in));
      assertEquals(1, s.getStats().getMalformed());
    }
  }
}
