package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;
import org.jaria.clock.VirtualClock;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.PasswordHash;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/** Logging in: open servers, a shared secret, a user file with groups; refusals say why. */
class AuthTest {

  /** Few PBKDF2 rounds: the arithmetic is the same, the test is fast. */
  private static final int ROUNDS = 1000;

  static ArServerBase server(Authenticator auth) throws Exception {
    ArServerBase s = new ArServerBase(ServerOptions.builder().port(0).authenticator(auth).build());
    s.addData("stop", "stops", "none", "none", "Movement", Where.WORKER, (c, q, r) -> {});
    s.addData(
        "info",
        "says hi",
        "none",
        "string",
        "RobotInfo",
        Where.WORKER,
        (c, q, r) -> r.strToBuf("hi " + c.getUser()));
    s.open();
    return s;
  }

  private static ArServerUserInfo users() {
    return ArServerUserInfo.parse(
        List.of(
            "# operators",
            ArServerUserInfo.makeLine("operator", "s3cret", ROUNDS, "all"),
            "",
            ArServerUserInfo.makeLine("visitor", "look", ROUNDS, "RobotInfo")),
        "users.txt");
  }

  private static int idOf(ArServerBase s, String name) {
    return s.dataList().stream().filter(d -> d.name().equals(name)).findFirst().orElseThrow().id();
  }

  /** A CHALLENGE's nonce, salt and rounds. */
  private static final class Challenge {
    final byte[] nonce;
    final byte[] salt;
    final int rounds;

    private Challenge(ArNetPacket p) {
      p.bufToStr();
      p.bufToLong();
      p.bufToStr();
      nonce = p.bufToData();
      salt = p.bufToData();
      rounds = p.bufToInt();
    }

    static Challenge read(ArNetPacket p) {
      return new Challenge(p);
    }

    byte[] nonce() {
      return nonce;
    }

    byte[] salt() {
      return salt;
    }

    int rounds() {
      return rounds;
    }
  }

  @Test
  void openServerLetsAnybodyIn() throws Exception {
    try (ArServerBase s = server(Authenticator.open());
        ArClientBase c = new ArClientBase("t")) {
      c.connect("127.0.0.1", s.getPort(), "anyone", null);
      assertEquals("hi anyone", Futures.get(c.requestOnce("info")).bufToStr());
      assertEquals(1, s.getNumClients());
      assertEquals("anyone", s.getClients().get(0).getUser());
      assertEquals("t", s.getClients().get(0).getClientName());
    }
  }

  @Test
  void sharedSecretRightAndWrong() throws Exception {
    try (ArServerBase s = server(Authenticator.sharedSecret("pioneer"))) {
      try (ArClientBase good = new ArClientBase("good")) {
        good.connect("127.0.0.1", s.getPort(), "me", "pioneer");
        assertTrue(good.isConnected());
      }
      try (ArClientBase bad = new ArClientBase("bad")) {
        ArClientException e =
            assertThrows(
                ArClientException.class,
                () -> bad.connect("127.0.0.1", s.getPort(), "me", "pioneeR"));
        assertEquals(NetError.BAD_LOGIN, e.getCode());
        assertEquals("login refused: wrong user name or password", e.getMessage());
        assertFalse(bad.isConnected());
        assertEquals(e.getMessage(), bad.getLastError());
      }
      assertEquals(1, s.getStats().getLoginFailed());
    }
  }

  @Test
  void userFileRightPasswordWrongPasswordUnknownUser() throws Exception {
    try (ArServerBase s = server(users())) {
      try (ArClientBase op = new ArClientBase("op")) {
        op.connect("127.0.0.1", s.getPort(), "operator", "s3cret");
        assertTrue(op.dataExists("stop"));
      }
      for (String[] wrong : new String[][] {{"operator", "s3cre"}, {"nobody", "s3cret"}}) {
        try (ArClientBase c = new ArClientBase("x")) {
          ArClientException e =
              assertThrows(
                  ArClientException.class,
                  () -> c.connect("127.0.0.1", s.getPort(), wrong[0], wrong[1]));
          assertEquals(NetError.BAD_LOGIN, e.getCode(), wrong[0]);
        }
      }
      assertEquals(2, s.getStats().getLoginFailed());
    }
  }

  @Test
  void groupsLimitWhatAUserSeesAndMayCall() throws Exception {
    try (ArServerBase s = server(users());
        ArClientBase v = new ArClientBase("v");
        RawClient raw = new RawClient(s.getPort())) {
      v.connect("127.0.0.1", s.getPort(), "visitor", "look");
      assertTrue(v.dataExists("info"));
      assertFalse(v.dataExists("stop"), "Movement data is not listed for a RobotInfo user");
      assertEquals(NetError.UNKNOWN_DATA, Futures.failure(v.requestOnce("stop")).getCode());
      // Calling it by number anyway is refused by the server.
      assertEquals(Kind.WELCOME, raw.login("visitor", "look").kind());
      raw.send(Kind.CALL, 1, idOf(s, "stop"));
      ArNetPacket err = raw.readUntil(Kind.ERROR).body();
      assertEquals(1, err.bufToInt());
      assertEquals(idOf(s, "stop"), err.bufToInt());
      assertEquals(NetError.NOT_ALLOWED.code(), err.bufToLong());
      assertEquals("user 'visitor' may not use Movement data", err.bufToStr());
    }
  }

  @Test
  void unknownUsersGetABelievableChallenge() throws Exception {
    try (ArServerBase s = server(users());
        RawClient a = new RawClient(s.getPort());
        RawClient b = new RawClient(s.getPort())) {
      a.send(Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, "a", "nobody");
      b.send(Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, "b", "nobody");
      Challenge ca = Challenge.read(a.read().body());
      Challenge cb = Challenge.read(b.read().body());
      assertEquals(PasswordHash.SALT_BYTES, ca.salt().length);
      assertEquals(PasswordHash.DEFAULT_ITERATIONS, ca.rounds());
      assertEquals(
          HexFormat.of().formatHex(ca.salt()),
          HexFormat.of().formatHex(cb.salt()),
          "the same salt every time, as for a real user");
      assertFalse(
          HexFormat.of().formatHex(ca.nonce()).equals(HexFormat.of().formatHex(cb.nonce())),
          "a fresh nonce every time");
    }
  }

  @Test
  void aCapturedLoginCannotBeReplayed() throws Exception {
    try (ArServerBase s = server(users());
        RawClient first = new RawClient(s.getPort());
        RawClient second = new RawClient(s.getPort())) {
      first.send(Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, "a", "operator");
      Challenge c = Challenge.read(first.read().body());
      byte[] proof =
          PasswordHash.proof(PasswordHash.derive("s3cret", c.salt(), c.rounds()), c.nonce());
      second.send(Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, "b", "operator");
      assertEquals(Kind.CHALLENGE, second.read().kind());
      second.send(Kind.LOGIN, (Object) proof);
      assertEquals(NetError.BAD_LOGIN.code(), second.readUntilClosed());
      first.send(Kind.LOGIN, (Object) proof);
      assertEquals(Kind.WELCOME, first.read().kind());
    }
  }

  @Test
  void anotherProtocolVersionIsRefusedWithAReason() throws Exception {
    try (ArServerBase s = server(Authenticator.open());
        RawClient raw = new RawClient(s.getPort())) {
      raw.send(Kind.HELLO, Protocol.MAGIC, 99, "future", "");
      RawClient.Frame f = raw.read();
      assertEquals(Kind.REFUSED, f.kind());
      assertEquals(NetError.BAD_VERSION.code(), f.body().bufToLong());
      String why = f.body().bufToStr();
      assertTrue(why.contains("protocol version 1 and the client 99"), why);
      assertEquals(-1, raw.readUntilClosed(), "then closed");
    }
  }

  @Test
  void wrongMagicOrWrongOrderClosesTheConnection() throws Exception {
    try (ArServerBase s = server(Authenticator.open())) {
      try (RawClient raw = new RawClient(s.getPort())) {
        raw.send(Kind.HELLO, "HTTP", 1, "x", "");
        assertEquals(NetError.MALFORMED.code(), raw.readUntilClosed());
      }
      try (RawClient raw = new RawClient(s.getPort())) {
        raw.send(Kind.CALL, 1, 1);
        assertEquals(NetError.PROTOCOL.code(), raw.readUntilClosed());
      }
      try (RawClient raw = new RawClient(s.getPort())) {
        assertEquals(Kind.WELCOME, raw.login("u", null).kind());
        raw.send(Kind.HELLO, Protocol.MAGIC, 1, "again", "");
        assertEquals(NetError.PROTOCOL.code(), raw.readUntilClosed());
      }
      assertEquals(3, s.getStats().getMalformed());
    }
  }

  @Test
  void aConnectionThatDoesNotLogInIsDropped() throws Exception {
    VirtualClock clock = new VirtualClock();
    try (ArServerBase s =
        new ArServerBase(
            ServerOptions.builder()
                .port(0)
                .loginTimeout(Duration.ofSeconds(5))
                .timeoutClock(clock)
                .build())) {
      s.open();
      try (RawClient silent = new RawClient(s.getPort())) {
        Eventually.until("accepted", () -> s.getClients().size() == 1);
        clock.advance(Duration.ofSeconds(6));
        assertEquals(NetError.LOGIN_TIMEOUT.code(), silent.readUntilClosed());
        assertEquals(1, s.getStats().getLoginTimeouts());
      }
    }
  }

  @Test
  void userFileMistakesNameFileAndLine() {
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArServerUserInfo.parse(List.of("# x", "User bob plain:secret"), "users.txt"));
    assertTrue(e.getMessage().startsWith("users.txt:2: "), e.getMessage());
    String line = ArServerUserInfo.makeLine("bob", "pw", ROUNDS);
    IllegalArgumentException twice =
        assertThrows(
            IllegalArgumentException.class, () -> ArServerUserInfo.parse(List.of(line, line), "u"));
    assertTrue(twice.getMessage().contains("listed twice"));
    assertThrows(
        IllegalArgumentException.class,
        () -> ArServerUserInfo.parse(List.of("User bob pbkdf2-sha256:10:!!:!!"), "u"));
    assertThrows(IllegalArgumentException.class, () -> ArServerUserInfo.makeLine("two words", "p"));
    ArServerUserInfo ok = ArServerUserInfo.parse(List.of(line + " Movement"), "u");
    assertEquals(Set.of("bob"), ok.getUserNames());
    assertTrue(ok.find("bob").orElseThrow().hasGroupAccess("Movement"));
    assertFalse(ok.find("bob").orElseThrow().hasGroupAccess("ConfigEditing"));
    assertTrue(ok.find("bob").orElseThrow().hasGroupAccess(""), "ungrouped data is for everyone");
  }
}
