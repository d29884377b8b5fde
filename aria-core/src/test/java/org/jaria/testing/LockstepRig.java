package org.jaria.testing;

import java.io.IOException;
import java.io.UncheckedIOException;
import org.jaria.clock.VirtualClock;
import org.jaria.connection.PipeConnection;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.robot.ArRobot;

/**
 * An {@link ArRobot} and a {@link FakeRobot} joined by an in-memory pipe on a virtual clock, driven
 * in lockstep from the test's thread: every tick the fake robot reads and answers, sends a SIP when
 * one is due, and the robot runs a cycle when a SIP arrived (or every tick while connecting).
 */
public final class LockstepRig {

  /** Simulated milliseconds per tick. */
  public static final long TICK_MS = 10;

  public final VirtualClock clock = new VirtualClock();
  public final PipeConnection.Pair pipe = PipeConnection.pair(clock, "rig");
  public final FakeRobot fake;
  public final ArRobot robot;

  /** The SIP the fake robot sends every {@link #sipPeriodMs} while open; tests edit it. */
  public final StandardSip sip = new StandardSip();

  public long sipPeriodMs = 100;
  public boolean sendSips = true;
  private long sinceSip;
  private long sinceLoop;

  /** A rig whose robot does state reflection (the normal case). */
  public LockstepRig() {
    this(true);
  }

  /** A rig whose robot reflects state or sends motion commands once, as ARIA's flag says. */
  public LockstepRig(boolean doStateReflection) {
    try {
      pipe.b().open();
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    fake = new FakeRobot(pipe.b(), clock);
    robot = new ArRobot("rig", clock, doStateReflection);
    robot.setDeviceConnection(pipe.a());
  }

  /** Runs {@code ms} of virtual time; everything the robot sent has been read at the end. */
  public void run(long ms) {
    for (long t = 0; t < ms; t += TICK_MS) {
      tick();
    }
    try {
      fake.pump();
    } catch (IOException e) {
      // the client closed its end
    }
  }

  /** Runs until {@code done} or {@code maxMs} of virtual time; returns whether done. */
  public boolean runUntil(java.util.function.BooleanSupplier done, long maxMs) {
    for (long t = 0; t < maxMs; t += TICK_MS) {
      if (done.getAsBoolean()) {
        return true;
      }
      tick();
    }
    return done.getAsBoolean();
  }

  /** One tick. */
  public void tick() {
    clock.advanceMillis(TICK_MS);
    boolean sent = false;
    try {
      fake.pump();
      sinceSip += TICK_MS;
      if (fake.isOpen() && sendSips && sinceSip >= sipPeriodMs) {
        sinceSip = 0;
        fake.sendSip(sip);
        sent = true;
      }
    } catch (IOException e) {
      // the client closed its end; the robot notices on its side
    }
    sinceLoop += TICK_MS;
    // Like the robot's own run loop: a cycle per SIP, or after two cycle times without one.
    if (sent || robot.isConnecting() || sinceLoop >= 2 * robot.getCycleTime()) {
      sinceLoop = 0;
      robot.loopOnce();
    }
  }

  /** Connects with asyncConnect and runs until connected; returns whether it worked. */
  public boolean connect() {
    robot.asyncConnect();
    return runUntil(() -> !robot.isConnecting(), 30_000) && robot.isConnected();
  }
}
