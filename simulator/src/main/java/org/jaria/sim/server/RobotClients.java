package org.jaria.sim.server;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.DropCounters;
import org.jaria.sim.robot.RobotBody;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Every connection to one simulated robot, and the rule that decides which one drives it. As with
 * MobileSim, one client at a time holds the robot; what makes squatting its port useless is when a
 * connection starts to hold it:
 *
 * <ul>
 *   <li>A connection that has not completed the ARCOS handshake (SYNC0, SYNC1, SYNC2) never holds
 *       the robot. It waits beside it, has the host's short handshake time to finish (2 s by
 *       default), and at most {@link #MAX_CANDIDATES} wait at once: a newcomer beyond that closes
 *       the stalest of them ({@link HoldRules#stalest}).
 *   <li>The robot's answer to SYNC2 is the moment a client takes it. If the robot is free, the
 *       client gets it at once; if its holder has sent no valid packet for the host's replace time
 *       (2 s by default: the watchdog has stopped the robot), the holder is disconnected and the
 *       newcomer gets it ({@link HoldRules#replaceable}); otherwise the newcomer's SYNC2 stays
 *       unanswered until the robot is free or its handshake time is up. A program that disconnects
 *       and reconnects at once thus gets its robot back.
 *   <li>A holder that sends CLOSE goes back to waiting beside the robot, which is free again.
 * </ul>
 *
 * <p>Garbage is not activity: only whole, valid packets count. Driven by the world thread.
 */
public final class RobotClients {

  private static final Logger log = LoggerFactory.getLogger(RobotClients.class);

  /** Connections in their handshake one robot keeps at once. */
  public static final int MAX_CANDIDATES = 64;

  private final RobotBody body;
  private final SessionHost host;
  private final DropCounters drops;
  private final LogRateLimit refusalLog;
  private final ArcosSession.Gate gate = this::mayHold;
  private final List<ArcosSession> candidates = new ArrayList<>();
  private final long[] connectedAt = new long[MAX_CANDIDATES];
  private final long[] lastPacketAt = new long[MAX_CANDIDATES];
  private final boolean[] sentPacket = new boolean[MAX_CANDIDATES];
  private ArcosSession holder;
  private long connections;
  private long refused;
  private long timedOut;
  private long replaced;

  /**
   * The clients of {@code body}'s port.
   *
   * @param drops the robot's drop counters (kept across sessions)
   * @param refusalLog how often a line about refused connections may be logged
   */
  public RobotClients(
      RobotBody body, SessionHost host, DropCounters drops, LogRateLimit refusalLog) {
    this.body = body;
    this.host = host;
    this.drops = drops;
    this.refusalLog = refusalLog;
  }

  /** Takes a new connection: it waits beside the robot until it completes the handshake. */
  public ArcosSession attach(ArDeviceConnection conn, ClientKind kind) {
    if (candidates.size() >= MAX_CANDIDATES) {
      int n = candidates.size();
      for (int i = 0; i < n; i++) {
        ArcosSession c = candidates.get(i);
        connectedAt[i] = c.connectedNanos();
        lastPacketAt[i] = c.lastPacketNanos();
        sentPacket[i] = c.sentPacket();
      }
      ArcosSession stalest =
          candidates.remove(HoldRules.stalest(connectedAt, lastPacketAt, sentPacket, n));
      stalest.end("made room for a newer connection");
      refuse("" + MAX_CANDIDATES + " connections were in their handshake; the stalest made room");
    }
    ArcosSession s = new ArcosSession(body, conn, host, drops, kind, gate);
    candidates.add(s);
    connections++;
    return s;
  }

  /** Reads and executes what every connection sent; lets a waiting client take a free robot. */
  public void poll(long now) {
    if (holder != null) {
      holder.poll(now);
      settleHolder();
    }
    for (int i = 0; i < candidates.size(); i++) {
      candidates.get(i).poll(now);
    }
    // the robot may have become free (or its holder silent): the longest waiting goes first
    for (int i = 0; i < candidates.size(); i++) {
      candidates.get(i).retryHold();
    }
    sweep();
  }

  /** Lets every connection send what is due and times out those that are too slow or silent. */
  public void afterPhysics(long now) {
    if (holder != null) {
      holder.afterPhysics(now);
      settleHolder();
    }
    for (int i = 0; i < candidates.size(); i++) {
      candidates.get(i).afterPhysics(now);
    }
    sweep();
  }

  /** The session holding the robot, or null. */
  public ArcosSession holder() {
    return holder;
  }

  /** Whether the robot has any connection (holding it or waiting beside it). */
  public boolean hasConnections() {
    return holder != null || !candidates.isEmpty();
  }

  /** Connections waiting beside the robot (not holding it). */
  public int waitingCount() {
    return candidates.size();
  }

  /** Ends every connection. */
  public void endAll(String why) {
    if (holder != null) {
      holder.end(why);
      holder = null;
    }
    for (ArcosSession c : candidates) {
      c.end(why);
    }
    candidates.clear();
  }

  /** Every connection, the holder first (to pull their cables in tests). */
  public List<ArcosSession> all() {
    List<ArcosSession> out = new ArrayList<>(candidates.size() + 1);
    if (holder != null) {
      out.add(holder);
    }
    out.addAll(candidates);
    return out;
  }

  /** Connections taken so far. */
  public long connections() {
    return connections;
  }

  /**
   * Connections closed because the robot had no room for them: the stalest in a full waiting list,
   * and clients whose handshake time ran out while the robot stayed taken.
   */
  public long refused() {
    return refused;
  }

  /** Connections ended because the handshake did not complete in time or the holder went silent. */
  public long timedOut() {
    return timedOut;
  }

  /** Silent holders replaced by a client that completed the handshake. */
  public long replaced() {
    return replaced;
  }

  private boolean mayHold(ArcosSession s) {
    if (holder == s) {
      return true;
    }
    settleHolder();
    if (holder != null) {
      long silent = TimeUnit.MILLISECONDS.toNanos(host.replaceSilentMillis());
      long now = host.clock().nanoTime();
      if (!HoldRules.replaceable(holder.kind(), holder.lastPacketNanos(), now, silent)) {
        return false;
      }
      holder.end(
          "sent nothing for "
              + host.replaceSilentMillis()
              + " ms and another client completed the handshake");
      replaced++;
      log.info(
          "{}: its silent client was replaced by {}", body.name(), s.connection().getPortName());
    }
    holder = s;
    return true;
  }

  /** Lets go of a holder that has ended or closed the robot (the latter waits beside it again). */
  private void settleHolder() {
    ArcosSession h = holder;
    if (h == null || h.holdsRobot()) {
      return;
    }
    holder = null;
    if (h.state() == ArcosSession.State.ENDED) {
      if (h.timedOut()) {
        timedOut++;
      }
    } else if (candidates.size() < MAX_CANDIDATES) {
      candidates.add(h);
    } else {
      h.end("closed the robot while " + MAX_CANDIDATES + " other connections waited");
    }
  }

  /** Forgets candidates that ended or now hold the robot, counting why they went. */
  private void sweep() {
    int kept = 0;
    for (int i = 0, n = candidates.size(); i < n; i++) {
      ArcosSession c = candidates.get(i);
      if (c == holder) {
        continue;
      }
      if (c.state() == ArcosSession.State.ENDED) {
        if (c.timedOut() && c.awaitingRobot()) {
          refuse("it stayed taken for the whole handshake time");
        } else if (c.timedOut()) {
          timedOut++;
        }
        continue;
      }
      candidates.set(kept++, c);
    }
    candidates.subList(kept, candidates.size()).clear();
  }

  private void refuse(String why) {
    refused++;
    long unlogged = refusalLog.record(host.clock().nanoTime());
    if (unlogged == 0) {
      log.warn("robot {}: connection refused: {}", body.name(), why);
    } else if (unlogged > 0) {
      log.warn(
          "robot {}: connection refused: {} ({} more refused since the last line)",
          body.name(),
          why,
          unlogged);
    }
  }
}
