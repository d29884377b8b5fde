package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;
import org.jaria.clock.Clock;
import org.jaria.clock.VirtualClock;
import org.jaria.connection.PipeConnection;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.Hex;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotModels;
import org.jaria.sim.SonarOptions;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.world.WorldGeometry;
import org.junit.jupiter.api.Test;

/**
 * Who holds a robot when many connections come to its port: squatters, garbage senders, silent
 * holders and a real client, all on in-memory connections and a virtual clock, ticked by hand.
 */
class RobotClientsTest {

  private static final byte[] SYNC0 = Hex.parse("FA FB 03 00 00 00");
  private static final byte[] SYNC1 = Hex.parse("FA FB 03 01 00 01");
  private static final byte[] SYNC2 = Hex.parse("FA FB 03 02 00 02");
  private static final byte[] OPEN = Hex.parse("FA FB 06 01 3B 01 00 02 3B");
  private static final byte[] CLOSE = Hex.parse("FA FB 06 02 3B 01 00 03 3B");

  private final VirtualClock clock = new VirtualClock();
  private final Host host = new Host(clock);
  private final RobotClients clients =
      new RobotClients(body(), host, new DropCounters("t"), new LogRateLimit(0));

  private static RobotBody body() {
    RandomGenerator[] r = new RandomGenerator[4];
    for (int i = 0; i < 4; i++) {
      r[i] = new SplittableRandom(i);
    }
    return new RobotBody(
        0,
        "t",
        RobotModels.forSubtype("p3dx-sh"),
        ArPose.ORIGIN,
        SonarOptions.DEFAULTS,
        OdometryError.NONE,
        r,
        false,
        false,
        false);
  }

  /** The client's end of one connection to the robot. */
  private final class Client {
    final PipeConnection end;
    final ArcosSession session;
    final List<Integer> ids = new ArrayList<>();
    private final ArRobotPacketReceiver rx = new ArRobotPacketReceiver(new DropCounters("c"));
    private final byte[] buf = new byte[4096];

    Client() {
      PipeConnection.Pair p = PipeConnection.pair(clock);
      try {
        p.a().open();
        p.b().open();
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
      end = p.a();
      session = clients.attach(p.b(), ClientKind.LOOPBACK_TCP);
    }

    void send(byte[] bytes) {
      try {
        end.write(bytes, 0, bytes.length);
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
    }

    /** Reads what arrived; false once the robot closed the connection. */
    boolean read() {
      try {
        int n;
        while ((n = end.read(buf, 0, buf.length, 0)) > 0) {
          rx.feed(buf, 0, n, clock.nanoTime(), (ArRobotPacket p) -> ids.add(p.getID()));
        }
        return n >= 0;
      } catch (IOException e) {
        return false;
      }
    }

    boolean closedByRobot() {
      return !read();
    }

    /** SYNC0..2 a tick apart, as the echoes come; true if SYNC2 was answered. */
    boolean handshake() {
      for (byte[] sync : new byte[][] {SYNC0, SYNC1, SYNC2}) {
        send(sync);
        tick();
      }
      read();
      return ids.contains(2);
    }
  }

  private void tick() {
    clients.poll(clock.nanoTime());
    clock.advanceMillis(10);
    clients.afterPhysics(clock.nanoTime());
  }

  private void ticks(int millis) {
    for (int i = 0; i < millis / 10; i++) {
      tick();
    }
  }

  @Test
  void squattersNeverHoldTheRobotAndGoAfterTheHandshakeTime() {
    List<Client> squatters = new ArrayList<>();
    for (int i = 0; i < 50; i++) {
      squatters.add(new Client());
    }
    ticks(500);
    Client real = new Client();
    assertTrue(real.handshake(), "SYNC2 answered past 50 squatters");
    assertSame(real.session, clients.holder());
    real.send(OPEN);
    ticks(1600);
    assertEquals(ArcosSession.State.OPEN, real.session.state());
    for (Client s : squatters) {
      assertTrue(s.closedByRobot(), "a squatter goes after the handshake time");
    }
    assertEquals(50, clients.timedOut());
    assertEquals(0, clients.waitingCount());
  }

  @Test
  void aSilentHolderIsReplacedByTheNextClientThatCompletesTheHandshake() {
    Client first = new Client();
    assertTrue(first.handshake());
    first.send(OPEN);
    tick();
    ticks(1000);
    Client next = new Client();
    assertFalse(next.handshake(), "the holder has been silent only 1 s: SYNC2 waits");
    assertTrue(next.session.awaitingRobot());
    ticks(1000);
    assertSame(next.session, clients.holder(), "silent 2 s: the newcomer takes the robot");
    next.read();
    assertTrue(next.ids.contains(2), "SYNC2 answered");
    assertTrue(first.closedByRobot());
    assertEquals(1, clients.replaced());
    assertEquals(0, clients.refused());
  }

  @Test
  void garbageIsNotActivity() {
    Client first = new Client();
    assertTrue(first.handshake());
    first.send(OPEN);
    tick();
    Client next = new Client();
    byte[][] handshake = {SYNC0, SYNC1, SYNC2};
    for (int i = 0; i < 250 && clients.holder() == first.session; i++) {
      first.send(new byte[] {(byte) 0xFA, 0x42}); // bytes every tick, never a packet
      if (i < handshake.length) {
        next.send(handshake[i]);
      }
      tick();
    }
    assertSame(next.session, clients.holder(), "a holder sending only garbage is replaced");
    next.send(OPEN);
    tick();
    assertEquals(ArcosSession.State.OPEN, next.session.state());
    assertEquals(1, clients.replaced());
  }

  @Test
  void aBusyHolderKeepsTheRobotAndTheNewcomerIsRefusedAtItsHandshakeTime() {
    Client first = new Client();
    assertTrue(first.handshake());
    first.send(OPEN);
    Client next = new Client();
    next.send(SYNC0);
    tick();
    next.send(SYNC1);
    tick();
    next.send(SYNC2);
    for (int i = 0; i < 250; i++) {
      if (i % 20 == 0) {
        first.send(SYNC0); // in an open session, a PULSE
      }
      tick();
    }
    assertSame(first.session, clients.holder());
    assertTrue(next.closedByRobot());
    assertFalse(next.ids.contains(2), "never answered");
    assertEquals(1, clients.refused());
    assertEquals(0, clients.replaced());
  }

  @Test
  void closeFreesTheRobotForAClientWaitingForIt() {
    Client first = new Client();
    assertTrue(first.handshake());
    first.send(OPEN);
    tick();
    Client next = new Client();
    assertFalse(next.handshake());
    first.send(CLOSE);
    tick();
    assertSame(next.session, clients.holder(), "the waiting client gets it in the same tick");
    assertEquals(ArcosSession.State.SYNC, first.session.state(), "the first may start again");
    assertEquals(1, clients.waitingCount());
  }

  @Test
  void aFullWaitingListClosesTheStalestSquatterNotAClientInItsHandshake() {
    List<Client> squatters = new ArrayList<>();
    for (int i = 0; i < RobotClients.MAX_CANDIDATES - 1; i++) {
      squatters.add(new Client());
    }
    Client real = new Client();
    real.send(SYNC0);
    tick();
    for (int i = 0; i < 10; i++) {
      squatters.add(new Client());
    }
    assertEquals(RobotClients.MAX_CANDIDATES, clients.waitingCount());
    assertEquals(10, clients.refused());
    for (int i = 0; i < 10; i++) {
      assertTrue(squatters.get(i).closedByRobot(), "the oldest squatters made room");
    }
    real.send(SYNC1);
    tick();
    real.send(SYNC2);
    tick();
    assertSame(real.session, clients.holder());
  }

  @Test
  void aClientThatEndsWithoutHoldingLeavesTheHolderAlone() {
    Client first = new Client();
    assertTrue(first.handshake());
    first.send(OPEN);
    tick();
    first.send(Hex.parse("FA FB 06 04 3B 01 00 05 3B")); // ENABLE
    tick();
    Client squatter = new Client();
    squatter.end.close();
    tick();
    assertSame(first.session, clients.holder());
    assertTrue(first.session.body.motion().areMotorsEnabled(), "a squatter leaving stops nothing");
  }

  @Test
  void inMemoryHoldersAreNeverReplaced() {
    assertTrue(HoldRules.replaceable(ClientKind.LOOPBACK_TCP, 0, 2000, 2000));
    assertFalse(HoldRules.replaceable(ClientKind.LOOPBACK_TCP, 1, 2000, 2000));
    assertFalse(HoldRules.replaceable(ClientKind.IN_MEMORY, 0, 1_000_000, 2000));
  }

  @Test
  void theStalestIsASilentConnectionFirstThenTheLongestQuiet() {
    long[] connected = {5, 1, 3, 2};
    long[] last = {9, 7, 4, 8};
    assertEquals(
        1, HoldRules.stalest(connected, last, new boolean[] {true, false, true, false}, 4));
    assertEquals(2, HoldRules.stalest(connected, last, new boolean[] {true, true, true, true}, 4));
    assertEquals(0, HoldRules.stalest(connected, last, new boolean[] {false, true, true, true}, 4));
    assertEquals(-1, HoldRules.stalest(connected, last, new boolean[4], 0));
    assertNull(clients.holder());
  }

  /** What sessions need from a world: time, and 2 s handshake and replace times. */
  private static final class Host implements SessionHost {
    private final Clock clock;
    private final WorldGeometry geometry = new WorldGeometry();

    Host(Clock clock) {
      this.clock = clock;
    }

    @Override
    public Clock clock() {
      return clock;
    }

    @Override
    public WorldGeometry world() {
      return geometry;
    }

    @Override
    public int sipCycleMillis() {
      return 100;
    }

    @Override
    public int watchdogMillis() {
      return 2000;
    }

    @Override
    public boolean watchdogWarnOnly() {
      return false;
    }

    @Override
    public void ignoredCommand(int command, IgnoredCommand.Reason reason, String robotName) {}

    @Override
    public void loadMapRequested(String path, int robotIndex) {}

    @Override
    public CommandPolicy commandPolicy() {
      return CommandPolicy.DEFAULT;
    }

    @Override
    public int handshakeTimeoutMillis() {
      return 2000;
    }

    @Override
    public int clientTimeoutMillis() {
      return 10_000;
    }

    @Override
    public int replaceSilentMillis() {
      return 2000;
    }

    @Override
    public void exitRequested(int code, String robotName) {}

    @Override
    public void ghostRequested(int robotIndex) {}

    @Override
    public boolean haveMap() {
      return false;
    }

    @Override
    public int simIntervalMillis() {
      return 10;
    }

    @Override
    public int realIntervalMillis() {
      return 0;
    }

    @Override
    public int lastIntervalMillis() {
      return 0;
    }
  }
}
