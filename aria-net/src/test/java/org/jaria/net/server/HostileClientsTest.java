package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.clock.VirtualClock;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Futures;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.jaria.robot.ArRobot;
import org.junit.jupiter.api.Test;

/**
 * The guiServer's answers to the hostile clients of its second round: sockets that squat the login
 * slots, an open server exposed to the network, a user whose long strings would break {@code
 * update} for everybody, and password guesses rotated over many addresses.
 */
class HostileClientsTest {

  private static ArServerBase passwordServer(ServerOptions.Builder b) throws Exception {
    ArServerBase s =
        new ArServerBase(
            b.port(0).udp(false).authenticator(Authenticator.sharedSecret("pw")).build());
    s.addData("hi", "", "none", "string", "", Where.WORKER, (c, q, r) -> r.strToBuf("hi"));
    s.open();
    return s;
  }

  /** A socket that reads the introduction and then never says a word. */
  private static RawClient squatter(int port, String from) throws Exception {
    RawClient r = new RawClient(port, 0, from);
    r.readIntroduction();
    return r;
  }

  @Test
  void squattersRenewingTheirSocketsKeepNoRealUserOut() throws Exception {
    try (ArServerBase s = passwordServer(ServerOptions.builder())) {
      List<RawClient> squatters = new ArrayList<>();
      int served = 0;
      try {
        for (int i = 0; i < 8; i++) {
          squatters.add(squatter(s.getPort(), null));
        }
        // The attack: eight silent sockets on 127.0.0.1, renewed one at a time, while a
        // real user tries to log in 30 times from the same address.
        for (int round = 0; round < 30; round++) {
          squatters.remove(0).close();
          squatters.add(squatter(s.getPort(), null));
          try (ArClientBase real = new ArClientBase("real")) {
            real.connect("127.0.0.1", s.getPort(), "anyone", "pw");
            served++;
          } catch (ArClientException e) {
            // counted below
          }
        }
      } finally {
        for (RawClient r : squatters) {
          r.close();
        }
      }
      assertEquals(30, served, "real logins served while 8 sockets squatted");
      assertTrue(s.getStats().getReplacedPending() > 0, "the squatters replaced each other");
    }
  }

  @Test
  void atTheCeilingTheLoopbackStillGetsIn() throws Exception {
    try (ArServerBase s =
        passwordServer(ServerOptions.builder().maxPendingLogins(8).maxPendingLoginsPerAddress(2))) {
      List<RawClient> squatters = new ArrayList<>();
      try {
        // Four "other computers" (other loopback addresses), two sockets each: the ceiling.
        for (int a = 2; a <= 5; a++) {
          for (int k = 0; k < 2; k++) {
            squatters.add(squatter(s.getPort(), "127.0.0." + a));
          }
        }
        try (ArClientBase real = new ArClientBase("real")) {
          real.connect("127.0.0.1", s.getPort(), "anyone", "pw");
          assertEquals("hi", Futures.get(real.requestOnce("hi")).bufToStr());
        }
        assertEquals(1, s.getStats().getReplacedPending());
      } finally {
        for (RawClient r : squatters) {
          r.close();
        }
      }
    }
  }

  @Test
  void anOpenServerDrivingARobotRefusesToListenBeyondTheLoopback() throws Exception {
    ArRobot robot = new ArRobot("exposed");
    ServerOptions everywhere = ServerOptions.builder().port(0).bindAddress("0.0.0.0").build();
    try (ArServerBase s = new ArServerBase(everywhere, robot)) {
      IllegalStateException e = assertThrows(IllegalStateException.class, s::open);
      assertTrue(e.getMessage().contains("anybody who can reach port"), e.getMessage());
      assertTrue(!s.isOpen());
    }
    try (ArServerBase s =
        new ArServerBase(everywhere.toBuilder().openBeyondLoopback(true).build(), robot)) {
      s.open();
      assertEquals("0.0.0.0", s.getAddress(), "every interface, said and meant");
    }
    try (ArServerBase s = new ArServerBase(ServerOptions.builder().port(0).build(), robot)) {
      s.open();
      assertEquals("127.0.0.1", s.getAddress(), "without a login, this computer only");
    }
  }

  @Test
  void aStatusLineIsCutWhateverAModeWritesInIt() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      var chatty =
          new org.jaria.net.server.modes.ArServerMode(rig.gui.getServer(), rig.robot, "Chatty") {
            @Override
            protected void onActivate() {
              setStatus("x".repeat(40_000));
            }

            @Override
            protected void onDeactivate() {}
          };
      assertTrue(rig.gui.getServer().runOnCycle(chatty::activate));
      rig.run(300);
      assertEquals(TextLimits.MAX_MESSAGE, chatty.getStatus().length());
      ArNetPacket update = rig.call("update");
      assertTrue(update.getDataLength() < 700, "update: " + update.getDataLength() + " bytes");
    }
  }

  @Test
  void aHandlerThatThrowsAHugeMessageStillAnswersItsClient() throws Exception {
    try (ArServerBase s = new ArServerBase(ServerOptions.builder().port(0).udp(false).build());
        ArClientBase c = new ArClientBase("c")) {
      s.addData(
          "echo",
          "",
          "string",
          "string",
          "",
          Where.WORKER,
          (client, q, r) -> {
            throw new IllegalArgumentException("no such thing: " + q.bufToStr());
          });
      s.open();
      c.connect("127.0.0.1", s.getPort(), "", "");
      ArClientException e = Futures.failure(c.requestOnce("echo", "E".repeat(31_000)));
      assertEquals(NetError.FAILED, e.getCode());
      assertTrue(e.getMessage().length() <= TextLimits.MAX_MESSAGE, e.getMessage().length() + "");
      // The next request is served as usual: nothing broke on the worker.
      Futures.failure(c.requestOnce("echo", "short"));
    }
  }

  @Test
  void guessesRotatedOverAddressesMeetTheGlobalRateButAKnownAddressDoesNot() throws Exception {
    VirtualClock frozen = new VirtualClock();
    try (ArServerBase s =
        passwordServer(ServerOptions.builder().timeoutClock(frozen).maxLoginChecksPerSecond(3))) {
      try (RawClient me = new RawClient(s.getPort())) {
        assertEquals(Protocol.SERVER_CONNECTED, me.login("me", "pw").getCommand());
      }
      // The bucket held 3 checks and the login above took one; the clock does not run.
      int checked = 0;
      for (int a = 2; a <= 6; a++) {
        try (RawClient guess = new RawClient(s.getPort(), 0, "127.0.0." + a)) {
          ArNetPacket answer = guess.login("admin", "guess" + a);
          assertEquals(Protocol.SERVER_REJECTED, answer.getCommand());
          assertEquals(Protocol.REJECTED_BAD_LOGIN, answer.bufToByte2());
          if (answer.bufToStr().isEmpty()) {
            checked++;
          }
        }
      }
      assertEquals(2, checked, "the rest were refused unchecked");
      assertEquals(3, s.getStats().getLoginBusy());
      try (RawClient me = new RawClient(s.getPort())) {
        assertEquals(
            Protocol.SERVER_CONNECTED,
            me.login("me", "pw").getCommand(),
            "an address that logged in before is not slowed by the guesses");
      }
    }
  }
}
