package org.jaria.sim;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.jaria.geom.ArPose;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.world.WorldGeometry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robots of a world: adding one (numbering, placing, registering its footprint and port) and
 * removing one (ending its session, closing its port, forgetting its footprint), so that nothing
 * else in the world keeps a robot that left. Robot numbers are never reused, so a number in a ray
 * hit, a pending map request or a picture of the world names one robot only. Runs under the world's
 * lock; the list is changed only between the passes of a step, never while one iterates over it.
 */
final class WorldRobots {

  private static final Logger log = LoggerFactory.getLogger(WorldRobots.class);

  private final SimWorld world;
  private final WorldStatics statics;
  private final WorldGeometry geometry;
  private final WorldServing serving;
  private final List<RobotSlot> slots = new ArrayList<>();
  private int nextNumber;
  private double maxSpeed;

  WorldRobots(SimWorld world, WorldStatics statics, WorldGeometry geometry, WorldServing serving) {
    this.world = world;
    this.statics = statics;
    this.geometry = geometry;
    this.serving = serving;
  }

  /**
   * Adds a robot with the next number; {@code factory} is the factory that made it for one client
   * (then it has no port of its own), or null.
   */
  RobotSlot add(RobotOptions o, RobotFactory factory) {
    statics.rebuild();
    int number = nextNumber;
    RobotModel model = RobotModels.forSubtype(o.subtype(), world.getOptions().profile());
    String name = o.name() != null ? o.name() : o.subtype() + "_" + (number + 1);
    ArPose start =
        o.startPose() != null
            ? o.startPose()
            : Placement.freeSpot(statics.map().home(), model, geometry);
    RobotSlot slot =
        RobotSlot.create(world, number, o, world.getOptions(), model, name, start, factory);
    if (factory == null) {
      serving.robotAdded(slot); // may throw (port in use): nothing is registered yet
    }
    nextNumber++;
    geometry.addRobot(number, slot.body.footprint());
    maxSpeed = Math.max(maxSpeed, model.getTransVelTop());
    slots.add(slot);
    log.info("added robot {} ({}) at {}", name, model.getSubtype(), start);
    return slot;
  }

  /**
   * Makes {@code factory}'s robot for the client {@code c}, which just connected: named after the
   * client's address, at the factory's start pose or the nearest free spot to it.
   */
  RobotSlot makeFor(RobotFactory factory, SocketChannel c) {
    statics.rebuild();
    String client;
    try {
      client =
          c.getRemoteAddress() instanceof InetSocketAddress a
              ? a.getAddress().getHostAddress() + ":" + a.getPort()
              : String.valueOf(c.getRemoteAddress());
    } catch (IOException e) {
      client = "client-" + nextNumber; // its session will find the connection broken
    }
    RobotOptions o = factory.robotFor(client, statics.map());
    ArPose at = o.startPose() != null ? o.startPose() : statics.map().home();
    RobotModel model = RobotModels.forSubtype(o.subtype(), world.getOptions().profile());
    return add(o.withStartPose(Placement.freeSpot(at, model, geometry)), factory);
  }

  /**
   * Takes {@code slot} out of the world: its client is told goodbye, its port closes, rays and
   * collisions stop seeing it, pictures of the world no longer show it. Returns whether it was
   * there.
   */
  boolean remove(RobotSlot slot, String why) {
    if (!slots.remove(slot)) {
      return false;
    }
    slot.endSession(why);
    TcpServers.unbind(slot);
    geometry.removeRobot(slot.body.index());
    slot.removed = true;
    maxSpeed = 0;
    for (RobotSlot s : slots) {
      maxSpeed = Math.max(maxSpeed, s.body.model().getTransVelTop());
    }
    if (slot.factory != null) {
      slot.factory.robotRemoved();
    }
    log.info("removed robot {}: {}", slot.body.name(), why);
    return true;
  }

  /** Removes every robot a factory made whose client has gone (MobileSim destroys them). */
  void removeOrphans() {
    for (int i = slots.size() - 1; i >= 0; i--) {
      RobotSlot s = slots.get(i);
      if (s.isOrphan()) {
        remove(s, "its client disconnected (a robot factory's robot lives as long as its client)");
      }
    }
  }

  /** The robot numbered {@code number}, or null if there is none (any more). */
  RobotSlot byNumber(int number) {
    for (RobotSlot s : slots) {
      if (s.body.index() == number) {
        return s;
      }
    }
    return null;
  }

  /** The handles of the robots in the world, in the order they were added. */
  List<SimRobot> handles() {
    List<SimRobot> out = new ArrayList<>(slots.size());
    for (RobotSlot s : slots) {
      out.add(s.handle);
    }
    return out;
  }

  /**
   * The handle of robot {@code number}.
   *
   * @throws IndexOutOfBoundsException if there is no such robot (any more)
   */
  SimRobot handle(int number) {
    RobotSlot s = byNumber(number);
    if (s == null) {
      throw new IndexOutOfBoundsException(
          "no robot number " + number + " in this world; see getRobots() for those there are");
    }
    return s.handle;
  }

  /** The robot named {@code name}, if any. */
  Optional<SimRobot> named(String name) {
    return slots.stream().filter(s -> s.body.name().equals(name)).map(s -> s.handle).findFirst();
  }

  /** The robots in the world, in the order they were added (the live list: do not change it). */
  List<RobotSlot> slots() {
    return slots;
  }

  /** The top speed of the fastest robot, mm/s (how far robots can move in a tick). */
  double maxSpeed() {
    return maxSpeed;
  }
}
