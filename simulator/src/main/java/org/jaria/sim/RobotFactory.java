package org.jaria.sim;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.world.WorldMap;

/**
 * MobileSim's robot factory ({@code -R MODEL}): a TCP port where every client that connects gets a
 * robot of its own, made for it at the start place and taken out of the world when the client
 * disconnects (or is dropped after its timeout). Any number of clients can be connected at once.
 * Made by {@link SimWorld#addRobotFactory}; its port opens with the world's other ports ({@link
 * SimWorld#listen()}).
 *
 * <p>As in MobileSim, a factory's robot is named after its client's address; here the client's port
 * is added ({@code 127.0.0.1:53412}) so that two clients on one machine get robots with two names.
 * It starts where {@link StartPose} says, moved aside (as every start is) if another robot stands
 * there. Thread-safe: every method takes the world's lock.
 */
public final class RobotFactory {

  /**
   * Where a factory's next robot starts: called on the world's thread for each new client, with the
   * world's current map.
   */
  @FunctionalInterface
  public interface StartPose {

    /** The start pose of the next robot, or null for the map's start position. */
    ArPose next(WorldMap map);

    /** The map's start position (its first RobotHome, else Dock, else the origin). */
    static StartPose home() {
      return map -> null;
    }
  }

  private final SimWorld world;
  private final RobotOptions template;
  private final StartPose start;

  /** Port asked for (0: any free port). */
  final int requestedPort;

  // Guarded by the world's lock (its methods and the world thread take it; it is reentrant).
  @GuardedBy("world.lock")
  private int boundPort = -1;

  @GuardedBy("world.lock")
  private long made;

  @GuardedBy("world.lock")
  private int inWorld;

  RobotFactory(SimWorld world, RobotOptions template, int port, StartPose start) {
    if (port < 0 || port > 65535) {
      throw new IllegalArgumentException("a robot factory's port must be 0..65535, was " + port);
    }
    this.world = world;
    this.template = template;
    this.requestedPort = port;
    this.start = start == null ? StartPose.home() : start;
  }

  /** The model of the robots it makes, e.g. {@code p3dx-sh}. */
  public String getModel() {
    return template.subtype();
  }

  /** The TCP port clients connect to, or -1 before {@link SimWorld#listen()}. */
  public int getPort() {
    world.lock.lock();
    try {
      return boundPort;
    } finally {
      world.lock.unlock();
    }
  }

  /** Robots made so far (one per client that connected). */
  public long getRobotsMade() {
    world.lock.lock();
    try {
      return made;
    } finally {
      world.lock.unlock();
    }
  }

  /** Its robots that are in the world now (one per connected client). */
  public List<SimRobot> getRobots() {
    world.lock.lock();
    try {
      List<SimRobot> out = new ArrayList<>(inWorld);
      for (SimRobot r : world.getRobots()) {
        if (r.getFactory() == this) {
          out.add(r);
        }
      }
      return out;
    } finally {
      world.lock.unlock();
    }
  }

  /**
   * The options of the robot for a client at {@code clientAddress}: the template's, named after the
   * client, at the start pose (the caller moves it aside if the spot is taken).
   */
  RobotOptions robotFor(String clientAddress, WorldMap map) {
    world.lock.lock();
    try {
      made++;
      inWorld++;
      return template.withName(clientAddress).withStartPose(start.next(map));
    } finally {
      world.lock.unlock();
    }
  }

  /** One of its robots left the world. */
  void robotRemoved() {
    world.lock.lock();
    try {
      inWorld--;
    } finally {
      world.lock.unlock();
    }
  }

  /** Its port is open at {@code port}, or closed (-1). */
  void setBoundPort(int port) {
    world.lock.lock();
    try {
      boundPort = port;
    } finally {
      world.lock.unlock();
    }
  }

  @Override
  public String toString() {
    return "RobotFactory[" + getModel() + "]";
  }
}
