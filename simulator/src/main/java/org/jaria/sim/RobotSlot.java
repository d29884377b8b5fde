package org.jaria.sim;

import java.nio.channels.ServerSocketChannel;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import java.util.random.RandomGenerator;
import org.jaria.geom.ArPose;
import org.jaria.protocol.DropCounters;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.serial.AuxDevices;
import org.jaria.sim.server.ArcosSession;
import org.jaria.sim.server.LogRateLimit;
import org.jaria.sim.server.RobotClients;

/**
 * A robot in a world with its server side: TCP port (none for a robot a {@link RobotFactory} made
 * for one client), its clients (the one holding it and those in their handshake), drop counters.
 */
final class RobotSlot {

  final RobotBody body;
  final RobotOptions options;
  final DropCounters drops;
  final SimRobot handle;

  /** Port asked for (-1 automatic, 0 any free); unused for a factory's robot. */
  final int requestedPort;

  /** The factory that made this robot for its one client, or null for a robot with its own port. */
  final RobotFactory factory;

  /** Set once the robot has left its world; the handle then refuses new clients. */
  boolean removed;

  ServerSocketChannel server;
  int boundPort = -1;

  /** Every connection to the robot and who holds it. */
  final RobotClients clients;

  RobotSlot(
      SimWorld world,
      RobotBody body,
      RobotOptions options,
      int requestedPort,
      RobotFactory factory) {
    this.body = body;
    this.options = options;
    this.requestedPort = requestedPort;
    this.factory = factory;
    this.drops = new DropCounters(body.name());
    this.handle = new SimRobot(world, this);
    this.clients =
        new RobotClients(
            body,
            world.host(),
            drops,
            new LogRateLimit(
                TimeUnit.MILLISECONDS.toNanos(world.getOptions().server().refusalLogMillis())));
  }

  /** The session holding the robot, or null. */
  ArcosSession session() {
    return clients.holder();
  }

  /**
   * A new robot number {@code index}: its body, with one random stream per noisy part derived from
   * the world's seed and the robot's number (so adding robots in the same order gives the same
   * noise), and its port (none if {@code factory} made it).
   */
  static RobotSlot create(
      SimWorld world,
      int index,
      RobotOptions o,
      SimOptions options,
      RobotModel model,
      String name,
      ArPose start,
      RobotFactory factory) {
    RandomGenerator[] rngs = new RandomGenerator[4];
    for (int k = 0; k < rngs.length; k++) {
      long seed =
          options.seed() ^ (0x9E3779B97F4A7C15L * (index + 1)) ^ (0xC2B2AE3D27D4EB4FL * (k + 1));
      rngs[k] = new SplittableRandom(seed);
    }
    RobotBody body =
        new RobotBody(
            index,
            name,
            model,
            start,
            options.sonar(),
            options.odometryError(),
            rngs,
            o.laser(),
            o.gyro(),
            o.gripper(),
            options.profile());
    if (o.legacyLaserCommands()) {
      body.laser().setAcceptsLegacyCommands(true);
    }
    body.setSrisimCompat(o.srisimCompat());
    body.setAuxDevice(1, AuxDevices.create(o.ptzType()));
    int base = options.basePort();
    int port = o.port() >= 0 ? o.port() : (base == 0 ? 0 : base + index);
    return new RobotSlot(world, body, o, port, factory);
  }

  /** Lets every connection read and execute what its client sent. */
  void poll(long now) {
    clients.poll(now);
  }

  /** Lets every connection send what is due after the tick's physics. */
  void afterPhysics(long now) {
    clients.afterPhysics(now);
  }

  /** Whether a factory made this robot and its client has gone (so the robot leaves the world). */
  boolean isOrphan() {
    return factory != null && !clients.hasConnections();
  }

  /** Ends every connection to the robot. */
  void endSession(String why) {
    clients.endAll(why);
  }

  @Override
  public String toString() {
    return "robot " + body.name();
  }
}
