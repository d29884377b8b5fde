package org.jaria.net.server;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.BooleanSupplier;
import java.util.function.UnaryOperator;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.guiserver.GuiServer;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/**
 * A guiServer on a simulated robot in lockstep, with one client logged in. The network runs in real
 * time, the robot only when the test advances the world: {@link #await} waits for a reply and
 * advances the world only while the server has a command queued for the robot's cycle, so virtual
 * time does not run on while a request crosses the network.
 *
 * <p>Shared with arnl-net's tests through this module's test jar: they add SonARNL's services with
 * {@link Services} (see {@code ArnlRig} there).
 */
class GuiRig implements AutoCloseable {

  /** What a rig adds to the server before it opens: localization, path planning and the like. */
  interface Services {
    /**
     * Sets the services up on the robot and hands them to the server's builder; returns what {@link
     * GuiRig#close()} closes (null: nothing).
     */
    AutoCloseable install(SimulatedRobot sim, GuiServer.Builder b) throws Exception;
  }

  static final ArMap OFFICE = ArMap.loadBundled("office");

  final SimulatedRobot sim;
  final ArRobot robot;
  final AutoCloseable services;
  final GuiServer gui;
  final ArClientBase client;

  GuiRig(Services setup, UnaryOperator<GuiServer.Builder> configure) throws Exception {
    this(setup, configure, null, "", "");
  }

  private GuiRig(
      Services setup,
      UnaryOperator<GuiServer.Builder> configure,
      java.util.function.Consumer<GuiRig> beforeOpen,
      String user,
      String password)
      throws Exception {
    SimWorld world = SimWorld.bundled("office", SimOptions.builder().seed(3).build());
    sim = SimulatedRobot.connect(world, world.addRobot("p3dx-sh"));
    robot = sim.robot();
    GuiServer.Builder b =
        GuiServer.builder(robot)
            .options(ServerOptions.builder().port(0).minInterval(Duration.ofMillis(20)).build())
            .map(OFFICE, "office.map");
    services = setup.install(sim, b);
    gui = configure.apply(b).build();
    if (beforeOpen != null) {
      beforeOpen.accept(this);
    }
    gui.open();
    sim.runMillis(200);
    client = new ArClientBase("test");
    client.connect("127.0.0.1", gui.getServer().getPort(), user, password);
  }

  /**
   * As {@link #plain}, with {@code beforeOpen} adding services of its own before the server opens
   * (so the rig's client sees them), and the client logged in as {@code user}.
   */
  static GuiRig plain(
      UnaryOperator<GuiServer.Builder> configure,
      java.util.function.Consumer<GuiRig> beforeOpen,
      String user,
      String password)
      throws Exception {
    return new GuiRig(GuiRig::sonarAtHome, configure, beforeOpen, user, password);
  }

  /** A guiServer without localization or planning (goto drives straight). */
  static GuiRig plain(UnaryOperator<GuiServer.Builder> configure) throws Exception {
    return new GuiRig(GuiRig::sonarAtHome, configure);
  }

  /** Sonar only, and the odometry started where the robot really is (the map's home). */
  private static AutoCloseable sonarAtHome(SimulatedRobot sim, GuiServer.Builder b) {
    ArRobot robot = sim.robot();
    robot.lock();
    try {
      robot.addRangeDevice(new ArSonarDevice());
      robot.moveTo(sim.sim().getTruePose());
    } finally {
      robot.unlock();
    }
    return null;
  }

  /**
   * The future's value: waits for it, advancing the world only while the robot's cycle has a
   * command to apply.
   */
  <T> T await(CompletableFuture<T> f) throws Exception {
    long end = System.nanoTime() + Eventually.LIMIT.toNanos();
    while (true) {
      if (gui.getServer().getPendingCycleCommands() > 0) {
        sim.world().step();
      }
      try {
        return f.get(gui.getServer().getPendingCycleCommands() > 0 ? 0 : 1, TimeUnit.MILLISECONDS);
      } catch (TimeoutException e) {
        if (System.nanoTime() > end) {
          throw new AssertionError("no reply within " + Eventually.LIMIT, e);
        }
      } catch (ExecutionException e) {
        throw e.getCause() instanceof Exception x ? x : e;
      }
    }
  }

  /** Reads a ubyte4 count and that many strings (JAria's list layout). */
  static java.util.List<String> strings(ArNetPacket p) {
    int n = p.bufToArray();
    java.util.List<String> l = new java.util.ArrayList<>();
    for (int i = 0; i < n; i++) {
      l.add(p.bufToStr());
    }
    return l;
  }

  /** Reads strings to the end of the packet (ArNetworking's layout of getGoals). */
  static java.util.List<String> stringsToEnd(ArNetPacket p) {
    java.util.List<String> l = new java.util.ArrayList<>();
    while (p.hasMore()) {
      l.add(p.bufToStr());
    }
    return l;
  }

  /** Sends a request and waits for its reply (see {@link #await}). */
  ArNetPacket call(String name, Object... args) throws Exception {
    return await(client.requestOnce(name, args));
  }

  /** Runs the robot for {@code ms} of virtual time. */
  void run(long ms) {
    sim.runMillis(ms);
  }

  /** Runs the robot until {@code done}, at most {@code maxMs} of virtual time. */
  boolean runUntil(BooleanSupplier done, long maxMs) {
    return sim.runUntil(done, Duration.ofMillis(maxMs));
  }

  @Override
  public void close() {
    client.close();
    gui.close();
    if (services != null) {
      try {
        services.close();
      } catch (Exception e) {
        throw new IllegalStateException("the rig's services did not close", e);
      }
    }
    sim.close();
    sim.world().close();
  }
}
