package org.jaria.sim;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.clock.VirtualClock;

/**
 * How a world meets the outside: the robots' and robot factories' TCP ports and the thread that
 * steps the world in real time. Everything but {@link #stopRealTime} runs under the world's lock.
 */
final class WorldServing {

  private final ReentrantLock lock;
  private TcpServers servers;
  private RealTimeRunner runner;
  private java.net.InetAddress bindAddress;
  private final List<RobotFactory> factories = new ArrayList<>();

  WorldServing(ReentrantLock worldLock) {
    this.lock = worldLock;
  }

  /** Opens every factory's and robot's port, once (idempotent). */
  void listen(List<RobotSlot> slots) throws IOException {
    if (servers == null) {
      servers = TcpServers.openAll(slots, factories, bindAddress);
    }
  }

  /**
   * Adds a robot factory; its port opens now if the world listens already.
   *
   * @throws java.io.UncheckedIOException if its port cannot be opened
   */
  void factoryAdded(RobotFactory f) {
    if (servers != null) {
      try {
        servers.bind(f);
      } catch (IOException e) {
        throw new java.io.UncheckedIOException(e);
      }
    }
    factories.add(f);
  }

  /** The robot factories, in the order they were added. */
  List<RobotFactory> factories() {
    return List.copyOf(factories);
  }

  /** Listens on {@code address} only (null: every interface); before {@link #listen}. */
  void setBindAddress(java.net.InetAddress address) {
    if (servers != null) {
      throw new IllegalStateException("the world listens already; set the address before listen()");
    }
    bindAddress = address;
  }

  /** Opens the port of a robot added while listening. */
  void robotAdded(RobotSlot slot) {
    if (servers != null) {
      servers.bindLate(slot);
    }
  }

  /**
   * Gives clients that connected since the last tick to their robots (a factory's client to a new
   * robot made for it).
   */
  void acceptPending(VirtualClock clock, WorldRobots robots) {
    if (servers != null) {
      servers.acceptPending(
          (slot, c) -> TcpServers.attach(slot, c, clock),
          (factory, c) -> TcpServers.attach(robots.makeFor(factory, c), c, clock));
    }
  }

  /**
   * Throws if a real-time thread steps the world and the caller is not that thread.
   *
   * @throws IllegalStateException saying how to step by hand
   */
  void checkMayStep() {
    if (runner != null && !runner.isRunnerThread()) {
      throw new IllegalStateException(
          "the world runs in real time; stop it with stopRealTime() before stepping by hand");
    }
  }

  /** Starts the real-time thread unless one runs. */
  void startRealTime(SimWorld world, long tickNanos, double speedup) {
    if (runner == null) {
      runner = new RealTimeRunner(world, tickNanos, speedup);
      runner.start();
    }
  }

  /** Stops the real-time thread and waits for it, without holding the lock while waiting. */
  void stopRealTime() {
    RealTimeRunner r;
    lock.lock();
    try {
      r = runner;
    } finally {
      lock.unlock();
    }
    if (r != null) {
      r.stopAndJoin();
      lock.lock();
      try {
        if (runner == r) {
          runner = null;
        }
      } finally {
        lock.unlock();
      }
    }
  }

  boolean isRealTime() {
    return runner != null;
  }

  /** Simulated seconds per real second: 1 when stepped by hand, ≤ 0 when unthrottled. */
  double speedup() {
    RealTimeRunner r = runner;
    return r == null ? 1 : r.speedup();
  }

  /** Real milliseconds a tick should take (0 when stepped by hand or unthrottled). */
  int realIntervalMillis() {
    RealTimeRunner r = runner;
    return r == null ? 0 : r.realIntervalMillis();
  }

  /** Real milliseconds the last tick took (0 when stepped by hand). */
  int lastIntervalMillis() {
    RealTimeRunner r = runner;
    return r == null ? 0 : r.lastIntervalMillis();
  }

  /** Closes every port. */
  void closePorts(List<RobotSlot> slots) {
    for (RobotSlot s : slots) {
      TcpServers.unbind(s);
    }
    if (servers != null) {
      servers.close();
      servers = null;
    }
  }
}
