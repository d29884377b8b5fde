package org.jaria.sim;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.clock.VirtualClock;

/**
 * How a world meets the outside: the robots' and robot factories' TCP ports and the thread that
 * steps the world in real time. Its state is guarded by the world's lock, which every method takes
 * (it is reentrant: the world's own methods, which hold it already, call these), so Error Prone
 * checks each access; {@link #stopRealTime} lets go of it while it waits for the thread.
 */
final class WorldServing {

  private final ReentrantLock lock;

  @GuardedBy("lock")
  private TcpServers servers;

  @GuardedBy("lock")
  private RealTimeRunner runner;

  @GuardedBy("lock")
  private java.net.InetAddress bindAddress;

  @GuardedBy("lock")
  private final List<RobotFactory> factories = new ArrayList<>();

  WorldServing(ReentrantLock worldLock) {
    this.lock = worldLock;
  }

  /** Opens every factory's and robot's port, once (idempotent). */
  void listen(List<RobotSlot> slots) throws IOException {
    lock.lock();
    try {
      if (servers == null) {
        servers = TcpServers.openAll(slots, factories, bindAddress);
      }
    } finally {
      lock.unlock();
    }
  }

  /**
   * Adds a robot factory; its port opens now if the world listens already.
   *
   * @throws java.io.UncheckedIOException if its port cannot be opened
   */
  void factoryAdded(RobotFactory f) {
    lock.lock();
    try {
      if (servers != null) {
        try {
          servers.bind(f);
        } catch (IOException e) {
          throw new java.io.UncheckedIOException(e);
        }
      }
      factories.add(f);
    } finally {
      lock.unlock();
    }
  }

  /** The robot factories, in the order they were added. */
  List<RobotFactory> factories() {
    lock.lock();
    try {
      return List.copyOf(factories);
    } finally {
      lock.unlock();
    }
  }

  /** Listens on {@code address} only (null: every interface); before {@link #listen}. */
  void setBindAddress(java.net.InetAddress address) {
    lock.lock();
    try {
      if (servers != null) {
        throw new IllegalStateException(
            "the world listens already; set the address before listen()");
      }
      bindAddress = address;
    } finally {
      lock.unlock();
    }
  }

  /** Opens the port of a robot added while listening. */
  void robotAdded(RobotSlot slot) {
    lock.lock();
    try {
      if (servers != null) {
        servers.bindLate(slot);
      }
    } finally {
      lock.unlock();
    }
  }

  /**
   * Gives clients that connected since the last tick to their robots (a factory's client to a new
   * robot made for it).
   */
  void acceptPending(VirtualClock clock, WorldRobots robots) {
    lock.lock();
    try {
      if (servers != null) {
        servers.acceptPending(
            (slot, c) -> TcpServers.attach(slot, c, clock),
            (factory, c) -> TcpServers.attach(robots.makeFor(factory, c), c, clock));
      }
    } finally {
      lock.unlock();
    }
  }

  /**
   * Throws if a real-time thread steps the world and the caller is not that thread.
   *
   * @throws IllegalStateException saying how to step by hand
   */
  void checkMayStep() {
    lock.lock();
    try {
      if (runner != null && !runner.isRunnerThread()) {
        throw new IllegalStateException(
            "the world runs in real time; stop it with stopRealTime() before stepping by hand");
      }
    } finally {
      lock.unlock();
    }
  }

  /** Starts the real-time thread unless one runs. */
  void startRealTime(SimWorld world, long tickNanos, double speedup) {
    lock.lock();
    try {
      if (runner == null) {
        runner = new RealTimeRunner(world, tickNanos, speedup);
        runner.start();
      }
    } finally {
      lock.unlock();
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
    lock.lock();
    try {
      return runner != null;
    } finally {
      lock.unlock();
    }
  }

  /** Simulated seconds per real second: 1 when stepped by hand, ≤ 0 when unthrottled. */
  double speedup() {
    lock.lock();
    try {
      RealTimeRunner r = runner;
      return r == null ? 1 : r.speedup();
    } finally {
      lock.unlock();
    }
  }

  /** Real milliseconds a tick should take (0 when stepped by hand or unthrottled). */
  int realIntervalMillis() {
    lock.lock();
    try {
      RealTimeRunner r = runner;
      return r == null ? 0 : r.realIntervalMillis();
    } finally {
      lock.unlock();
    }
  }

  /** Real milliseconds the last tick took (0 when stepped by hand). */
  int lastIntervalMillis() {
    lock.lock();
    try {
      RealTimeRunner r = runner;
      return r == null ? 0 : r.lastIntervalMillis();
    } finally {
      lock.unlock();
    }
  }

  /** Closes every port. */
  void closePorts(List<RobotSlot> slots) {
    lock.lock();
    try {
      for (RobotSlot s : slots) {
        TcpServers.unbind(s);
      }
      if (servers != null) {
        servers.close();
        servers = null;
      }
    } finally {
      lock.unlock();
    }
  }
}
