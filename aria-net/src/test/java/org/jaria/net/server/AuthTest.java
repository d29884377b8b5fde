package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import org.jaria.clock.VirtualClock;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** ArNetworking's login: user files, groups, the login timeout, and mistakes that are refused. */
class AuthTest {

  private static ArServerUserInfo users() {
    return ArServerUserInfo.parse(
        List.of(
            "UserInfoVersion1",
            "; ARIA's comment style",
            "user operator drive all",
            "user visitor look RobotInfo"),
        "users");
  }

  private static ArServerBase server(Authenticator auth) throws IOException {
    ArServerBase s =
        new ArServerBase(ServerOptions.builder().port(0).udp(false).authenticator(auth).build());
    s.addData(
        "info", "", "none", "string: hi", "RobotInfo", Where.WORKER, (c, q, r) -> r.strToBuf("hi"));
    s.addData("stop", "", "none", "none", "Movement", Where.WORKER, (c, q, r) -> {});
    s.open();
    return s;
  }

  @Test
  void rightAndWrongPasswords() throws Exception {
    try (ArServerBase s = server(users());
        ArClientBase op = new ArClientBase("op");
        ArClientBase bad = new ArClientBase("bad")) {
      op.connect("127.0.0.1", s.getPort(), "OPERATOR", "drive");
      assertTrue(op.dataExists("stop"), "user names ignore case, as in ARIA");
      ArClientException e =
          assertThrows(
              ArClientException.class,
              () -> bad.connect("127.0.0.1", s.getPort(), "operator", "x"));
      assertEquals("login refused: wrong user name or password", e.getMessage());
      assertThrows(
          ArClientException.class, () -> bad.connect("127.0.0.1", s.getPort(), "nobody", "x"));
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
      assertTrue(Futures.failure(v.requestOnce("stop")).getMessage().contains("no data 'stop'"));
      // Calling it by number anyway is ignored and counted by the server, as ArNetworking does.
      assertEquals(Protocol.SERVER_CONNECTED, raw.login("visitor", "look").getCommand());
      long before = s.getStats().getRequestErrors();
      raw.requestOnce(s.findCommandFromName("stop"), new ArNetPacket());
      raw.requestOnce(s.findCommandFromName("info"), new ArNetPacket());
      assertEquals("hi", raw.readUntil(s.findCommandFromName("info")).bufToStr());
      assertEquals(before + 1, s.getStats().getRequestErrors());
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
        silent.readIntroduction();
        clock.advance(Duration.ofSeconds(6));
        assertEquals(-1, silent.readUntilClosed());
        Eventually.until("counted", () -> s.getStats().getLoginTimeouts() == 1);
      }
    }
  }

  @Test
  void userFileMistakesNameFileAndLine() {
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArServerUserInfo.parse(List.of("UserInfoVersion1", "user bob"), "users.txt"));
    assertTrue(e.getMessage().startsWith("users.txt:2: "), e.getMessage());
    assertThrows(
        IllegalArgumentException.class,
        () -> ArServerUserInfo.parse(List.of("user bob pw"), "u"),
        "the header line is required");
    String line = ArServerUserInfo.makeLine("bob", "pw");
    IllegalArgumentException twice =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArServerUserInfo.parse(List.of("UserInfoVersion1", line, line), "u"));
    assertTrue(twice.getMessage().contains("listed twice"));
    assertThrows(IllegalArgumentException.class, () -> ArServerUserInfo.makeLine("bob", "p w!"));
    ArServerUserInfo ok =
        ArServerUserInfo.parse(List.of("UserInfoVersion1", line + " Movement"), "u");
    assertEquals(Set.of("bob"), ok.getUserNames());
    assertTrue(ok.find("bob").orElseThrow().hasGroupAccess("movement"));
    assertFalse(ok.find("bob").orElseThrow().hasGroupAccess("ConfigEditing"));
    assertTrue(ok.find("bob").orElseThrow().hasGroupAccess(""), "ungrouped data is for everyone");
  }

  @Test
  void aUserFileOthersMayReadIsRefused(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("users.txt");
    Files.writeString(f, "UserInfoVersion1\nuser bob pw all\n");
    Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r--r--"));
    IOException e = assertThrows(IOException.class, () -> ArServerUserInfo.readFile(f));
    assertTrue(e.getMessage().contains("chmod 600"), e.getMessage());
    Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-------"));
    assertEquals(Set.of("bob"), ArServerUserInfo.readFile(f).getUserNames());
  }
}
