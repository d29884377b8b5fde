package org.jaria.sim;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.IntConsumer;
import java.util.function.Supplier;
import org.jaria.clock.Clock;
import org.jaria.clock.VirtualClock;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.sim.camera.CameraScene;
import org.jaria.sim.camera.ColoredObjects;
import org.jaria.sim.server.CommandPolicy;
import org.jaria.sim.world.WorldGeometry;
import org.jaria.sim.world.WorldMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A simulated world (a MobileSim analogue): a map, robots that drive and sense in it, and an ARCOS
 * server per robot that any ARIA client can connect to, over TCP (port 8101, 8102, ...) or an
 * in-memory connection.
 *
 * <p>Time is virtual: {@link #step()} advances exactly one tick (10 ms by default) and {@link
 * #advance(Duration)} many, so a JUnit test runs a minute of robot time in well under a second, and
 * the same seed and commands always give the same run. {@link #startRealTime(double)} instead lets
 * a world thread step in step with the wall clock (times a speed-up), for external clients.
 *
 * <p>Each tick: new TCP clients are attached, every session reads and executes what its client
 * sent, every robot moves and senses, every session sends what is due (SIPs every SIP cycle and the
 * packets requested), then the step listeners run. All methods are thread-safe: they take the
 * world's lock, which a step holds while it runs.
 *
 * <pre>{@code
 * try (SimWorld world = SimWorld.create(ArMap.loadBundled("office"), SimOptions.defaults())) {
 *   SimRobot robot = world.addRobot("p3dx-sh");
 *   ArDeviceConnection conn = robot.connectInMemory(); // hand it to an ArRobot
 *   world.advance(Duration.ofSeconds(60));
 * }
 * }</pre>
 */
public final class SimWorld implements AutoCloseable, CameraScene {

  private static final Logger log = LoggerFactory.getLogger(SimWorld.class);

  /** The exit code the exit handler hears when the world thread fails (sysexits' EX_SOFTWARE). */
  public static final int EXIT_WORLD_FAILED = 70;

  /** Numbers worlds for their names (and their threads' names) only; holds no simulation state. */
  private static final AtomicInteger WORLD_NUMBERS = new AtomicInteger();

  final ReentrantLock lock = new ReentrantLock();
  private final SimOptions options;
  private final String name;
  private final VirtualClock clock;
  private final WorldGeometry geometry = new WorldGeometry();
  private final WorldStatics statics;
  private final List<Runnable> stepListeners = new CopyOnWriteArrayList<>();
  private final ColoredObjects colored =
      new ColoredObjects(
          outline -> {
            SimObstacle o = injectObstacle(outline);
            return () -> removeObstacle(o);
          });
  private final IgnoredCommandLog ignored = new IgnoredCommandLog();
  private final WorldHost host = new WorldHost(this);
  // The world's jobs: map and obstacles, ground-truth queries, the outside (TCP ports, real-time
  // thread), the robots, and the tick. This class holds the lock and the public API over them.
  private final WorldObstacles obstacles;
  private final WorldQueries queries;
  private final WorldServing serving = new WorldServing(lock);
  private final WorldRobots robots;
  private final WorldTick tick;
  private final ClientMapLoader mapLoader;
  private final CommandPolicy commandPolicy;
  private volatile IntConsumer exitHandler =
      code -> {
        if (code == EXIT_WORLD_FAILED) {
          log.warn("the simulator stopped (code {}); no exit handler ends the program", code);
        } else {
          log.warn("a client asked the simulator to exit with code {}; no exit handler", code);
        }
      };

  @GuardedBy("lock")
  private boolean closed;

  private SimWorld(WorldMap map, SimOptions options, VirtualClock clock) {
    this.statics = new WorldStatics(map, geometry);
    this.obstacles = new WorldObstacles(statics, geometry, colored);
    this.queries = new WorldQueries(statics, geometry);
    this.robots = new WorldRobots(this, statics, geometry, serving);
    this.options = options;
    this.clock = clock;
    this.tick =
        new WorldTick(this, clock, options.tick().toNanos(), statics, geometry, serving, robots);
    this.name =
        "world-" + WORLD_NUMBERS.incrementAndGet() + "-" + MapSupport.shortName(map.source());
    SimServerOptions so = options.server();
    Path folder = so.mapFolder() != null ? so.mapFolder() : Path.of("");
    this.mapLoader =
        new ClientMapLoader(
            new ClientMapFolder(folder, so.maxMapBytes())::read, "jaria-sim-maps-" + this.name);
    this.commandPolicy =
        new CommandPolicy(so.ignoredCommands(), so.remoteExit(), so.mapFolder() != null);
  }

  /**
   * The world's name: a number unique in this program and the name of the map it started with, e.g.
   * {@code world-3-office}. Its real-time thread is called {@code jaria-sim-} plus this name.
   */
  public String getName() {
    return name;
  }

  // ---------------------------------------------------------------- creation

  /** A world on the map {@code map}, advanced by the caller on {@code clock} (lockstep). */
  public static SimWorld create(ArMap map, SimOptions options, VirtualClock clock) {
    return of(map, "map", options, clock);
  }

  private static SimWorld of(ArMap map, String source, SimOptions options, VirtualClock clock) {
    SimWorld w = new SimWorld(MapSupport.fromArMap(map, source), options, clock);
    w.colored.replaceFromMap(map);
    return w;
  }

  /** A world on {@code map} with its own virtual clock. */
  public static SimWorld create(ArMap map, SimOptions options) {
    return create(map, options, new VirtualClock());
  }

  /** A world on an already converted map (lines and points), with its own virtual clock. */
  public static SimWorld create(WorldMap map, SimOptions options, VirtualClock clock) {
    return new SimWorld(map, options, clock);
  }

  /**
   * A world on a map file.
   *
   * @throws IOException if the file cannot be read or parsed (the message names file and line), or
   *     if the map is over the simulator's {@link MapBudget} (the message says which count)
   */
  public static SimWorld load(Path mapFile, SimOptions options) throws IOException {
    try {
      return of(ArMap.readFile(mapFile), mapFile.toString(), options, new VirtualClock());
    } catch (org.jaria.map.MapFormatException | MapBudget.MapTooBigException e) {
      throw new IOException(e.getMessage(), e);
    }
  }

  /** A world on one of the maps bundled with JAria ("office", "hall"). */
  public static SimWorld bundled(String name, SimOptions options) {
    return of(ArMap.loadBundled(name), "bundled:" + name, options, new VirtualClock());
  }

  /** A world without walls. */
  public static SimWorld empty(SimOptions options) {
    return new SimWorld(WorldMap.EMPTY, options, new VirtualClock());
  }

  /** A world with only the given walls; robots start at {@code home}. */
  public static SimWorld ofLines(List<ArLineSegment> walls, ArPose home, SimOptions options) {
    return new SimWorld(WorldMap.ofLines("lines", walls, home), options, new VirtualClock());
  }

  // ---------------------------------------------------------------- robots

  /**
   * Adds a robot of model {@code subtype} at the map's start position, with a gripper if the
   * world's profile gives one ({@link org.jaria.sim.robot.SimProfile#gripperByDefault()}).
   */
  public SimRobot addRobot(String subtype) {
    return addRobot(RobotOptions.of(subtype).withGripper(options.profile().gripperByDefault()));
  }

  /**
   * Adds a robot. If the world is listening ({@link #listen()}), its TCP port opens at once.
   *
   * @throws IllegalStateException if the world is closed
   * @throws java.io.UncheckedIOException if its TCP port cannot be opened
   */
  public SimRobot addRobot(RobotOptions o) {
    lock.lock();
    try {
      requireOpen();
      return robots.add(o, null).handle;
    } finally {
      lock.unlock();
    }
  }

  /**
   * Takes a robot out of the world: its client is disconnected, its TCP port closes, other robots'
   * sensors and bumpers stop meeting it from the next tick on, and {@link #snapshot()} and {@link
   * #getRobots()} no longer show it. Its number is not given to another robot; its handle then
   * answers with its last state and refuses new clients. Returns whether it was in this world.
   */
  public boolean removeRobot(SimRobot robot) {
    lock.lock();
    try {
      return robot.getWorld() == this && robots.remove(robot.slot(), "removed from the world");
    } finally {
      lock.unlock();
    }
  }

  /**
   * Adds a robot factory (MobileSim's {@code -R MODEL}): a TCP port where each client that connects
   * gets a new robot with the options {@code template}, starting where {@code start} says (null:
   * the map's start position), removed when its client disconnects. The port opens with {@link
   * #listen()} (at once if the world listens already).
   *
   * @param port the TCP port (0: any free port)
   * @throws IllegalArgumentException if the model is unknown or the port out of range
   * @throws java.io.UncheckedIOException if the world listens already and the port is in use
   */
  public RobotFactory addRobotFactory(
      RobotOptions template, int port, RobotFactory.StartPose start) {
    RobotModels.forSubtype(template.subtype()); // an unknown model fails now, not per client
    lock.lock();
    try {
      requireOpen();
      RobotFactory f = new RobotFactory(this, template, port, start);
      serving.factoryAdded(f);
      return f;
    } finally {
      lock.unlock();
    }
  }

  /** The robot factories, in the order they were added. */
  public List<RobotFactory> getRobotFactories() {
    return locked(serving::factories);
  }

  /** The robots, in the order they were added. */
  public List<SimRobot> getRobots() {
    return locked(robots::handles);
  }

  /**
   * The robot numbered {@code index} ({@link SimRobot#getIndex()}; the n-th robot added, counting
   * from 0).
   *
   * @throws IndexOutOfBoundsException if there is no such robot (any more)
   */
  public SimRobot getRobot(int index) {
    return locked(() -> robots.handle(index));
  }

  /** The robot named {@code name}, if any. */
  public Optional<SimRobot> findRobot(String name) {
    return locked(() -> robots.named(name));
  }

  // ---------------------------------------------------------------- time

  /**
   * Advances the world by exactly one tick, then runs the step listeners.
   *
   * @throws IllegalStateException if a real-time thread is stepping the world
   */
  public void step() {
    lock.lock();
    try {
      serving.checkMayStep();
      requireOpen();
      tick.run();
    } finally {
      lock.unlock();
    }
    for (Runnable r : stepListeners) {
      r.run();
    }
  }

  /** Advances the world by {@code d} (rounded up to whole ticks). */
  public void advance(Duration d) {
    for (long i = tick.ticksFor(d.toNanos()); i > 0; i--) {
      step();
    }
  }

  /** Advances the world by {@code ms} milliseconds. */
  public void advanceMillis(long ms) {
    advance(Duration.ofMillis(ms));
  }

  /** Calls {@code r} after every tick (on the stepping thread, outside the world's lock). */
  public void addStepListener(Runnable r) {
    stepListeners.add(r);
  }

  /** Stops calling {@code r}. */
  public void removeStepListener(Runnable r) {
    stepListeners.remove(r);
  }

  /** The world's clock (virtual: it moves only when the world steps). */
  public Clock getClock() {
    return clock;
  }

  /** The world's clock as a {@link VirtualClock}. */
  public VirtualClock getVirtualClock() {
    return clock;
  }

  /** Simulated time of one tick. */
  public Duration getTick() {
    return options.tick();
  }

  /** Ticks run so far. */
  public long getStepCount() {
    return locked(tick::steps);
  }

  /** The options the world was made with. */
  public SimOptions getOptions() {
    return options;
  }

  // ---------------------------------------------------------------- real time and TCP

  /**
   * Opens a TCP server for every robot (and for robots added later): the first on the base port,
   * the next on the following one, unless a robot asked for its own. Idempotent.
   *
   * @throws IOException if a port is in use (the message says which and what to do)
   */
  public void listen() throws IOException {
    lock.lock();
    try {
      requireOpen();
      serving.listen(robots.slots());
    } finally {
      lock.unlock();
    }
  }

  /**
   * Makes {@link #listen()} open the robots' ports on the interface with {@code address} only
   * (MobileSim's {@code --bind-to-address}); null, the default, listens on every interface.
   *
   * @throws IllegalStateException if the world listens already
   */
  public void setBindAddress(java.net.InetAddress address) {
    lock.lock();
    try {
      serving.setBindAddress(address);
    } finally {
      lock.unlock();
    }
  }

  /**
   * Starts a thread ("jaria-sim-" and the {@link #getName() world's name}) that steps the world in
   * real time times {@code speedup} (≤ 0: as fast as it can). Idempotent while running.
   */
  public void startRealTime(double speedup) {
    lock.lock();
    try {
      requireOpen();
      serving.startRealTime(this, options.tick().toNanos(), speedup);
    } finally {
      lock.unlock();
    }
  }

  /** Stops the real-time thread and waits for it to end; the world can then be stepped by hand. */
  public void stopRealTime() {
    serving.stopRealTime();
  }

  /** Whether a real-time thread is stepping the world. */
  public boolean isRealTime() {
    return locked(serving::isRealTime);
  }

  /** Simulated seconds per real second: 1 when stepped by hand, ≤ 0 when unthrottled. */
  double speedup() {
    return serving.speedup();
  }

  /** Real milliseconds a tick should take (0 when stepped by hand or unthrottled). */
  int realIntervalMillis() {
    return serving.realIntervalMillis();
  }

  /** Real milliseconds the last tick took (0 when stepped by hand). */
  int lastIntervalMillis() {
    return serving.lastIntervalMillis();
  }

  /**
   * What to do when a client sends SIM_EXIT (the command line ends its run), or with {@link
   * #EXIT_WORLD_FAILED} when the real-time thread fails. The handler runs on the stepping thread:
   * it should only signal another thread (which may then close the world), never block or close the
   * world itself.
   */
  public void setExitHandler(IntConsumer handler) {
    exitHandler = handler;
  }

  IntConsumer exitHandler() {
    return exitHandler;
  }

  // ---------------------------------------------------------------- map and obstacles

  /**
   * Replaces the map; robots move to free spots near the new map's start position.
   *
   * @throws MapBudget.MapTooBigException if the map is over the simulator's budget (the world keeps
   *     its map)
   */
  public void loadMap(ArMap newMap, String source) {
    whileLocked(() -> obstacles.loadMap(newMap, source, robots.slots()));
  }

  void setMap(WorldMap m) {
    whileLocked(() -> obstacles.setMap(m, robots.slots()));
  }

  /** Whether the world has a map with anything solid in it. */
  boolean haveMap() {
    return obstacles.haveMap();
  }

  /** The current map's physical content. */
  public WorldMap getMap() {
    return locked(obstacles::map);
  }

  /** Adds a wall that robots bump into and sensors see. */
  public SimObstacle injectObstacle(ArLineSegment wall) {
    return injectObstacle(List.of(wall));
  }

  /** Adds an obstacle made of several walls. */
  public SimObstacle injectObstacle(List<ArLineSegment> walls) {
    return locked(() -> obstacles.inject(walls));
  }

  /** Adds a rectangular box centred at (cx, cy), {@code w} × {@code h} mm, turned {@code thDeg}. */
  public SimObstacle injectBox(double cx, double cy, double w, double h, double thDeg) {
    return injectObstacle(WorldStatics.box(cx, cy, w, h, thDeg));
  }

  /** Removes an injected obstacle; returns whether it was there. */
  public boolean removeObstacle(SimObstacle o) {
    return locked(() -> obstacles.remove(o));
  }

  /** The injected obstacles. */
  public List<SimObstacle> getObstacles() {
    return locked(obstacles::list);
  }

  /**
   * Ground truth: the distance from (x, y) along {@code thDeg} to the nearest wall, obstacle or
   * robot, or {@link Double#POSITIVE_INFINITY} beyond {@code maxRange}.
   */
  public double castRay(double x, double y, double thDeg, double maxRange) {
    return castRay(x, y, thDeg, maxRange, null);
  }

  /**
   * As {@link #castRay(double, double, double, double)}, ignoring the robot {@code self} (for
   * sensors that sit inside their own robot's outline, such as a camera).
   */
  public double castRay(double x, double y, double thDeg, double maxRange, SimRobot self) {
    return locked(
        () -> queries.castRay(x, y, thDeg, maxRange, self == null ? -1 : self.getIndex()));
  }

  /** As above, ignoring robot number {@code self} (none if -1): what a camera sees. */
  @Override
  public double castRay(double x, double y, double thDeg, double maxRange, int self) {
    return locked(() -> queries.castRay(x, y, thDeg, maxRange, self));
  }

  /** The coloured objects cameras see (from the map, or added). */
  @Override
  public ColoredObjects coloredObjects() {
    return colored;
  }

  /** The world's seed ({@link SimOptions#seed()}), which a camera's noise derives from. */
  @Override
  public long seed() {
    return options.seed();
  }

  // ---------------------------------------------------------------- inspection

  /** A consistent picture of every robot and obstacle, safe to use from any thread. */
  public SimSnapshot snapshot() {
    return locked(() -> queries.snapshot(clock.nanoTime(), robots.slots()));
  }

  /** Number of robots with a client connected. */
  public int connectedClientCount() {
    return locked(() -> queries.connectedClientCount(robots.slots()));
  }

  /** What the robots' ports did with their clients so far. */
  public ServerCounters getServerCounters() {
    return locked(() -> queries.serverCounters(robots.slots()));
  }

  WorldHost host() {
    return host;
  }

  ClientMapLoader mapLoader() {
    return mapLoader;
  }

  CommandPolicy commandPolicy() {
    return commandPolicy;
  }

  /**
   * Waits until a map a client asked for has been read and parsed (it is applied on the next step).
   * For tests that step by hand and must not depend on how fast the loader thread is.
   */
  public void awaitClientMapLoad() throws InterruptedException {
    mapLoader.awaitIdle();
  }

  WorldGeometry geometry() {
    return geometry;
  }

  IgnoredCommandLog ignoredCommands() {
    return ignored;
  }

  /**
   * The commands the robots received but did not carry out (unknown numbers, commands the simulator
   * does not simulate, commands for devices a robot does not carry), with counts.
   */
  public List<org.jaria.sim.server.IgnoredCommand> getIgnoredCommands() {
    return locked(ignored::snapshot);
  }

  List<RobotSlot> slots() {
    return robots.slots();
  }

  /** The robot numbered {@code number}, or null if it is not (or no longer) in the world. */
  RobotSlot slotByNumber(int number) {
    return robots.byNumber(number);
  }

  /** Runs {@code query} under the world's lock. */
  private <T> T locked(Supplier<T> query) {
    lock.lock();
    try {
      return query.get();
    } finally {
      lock.unlock();
    }
  }

  /** Runs {@code change} under the world's lock. */
  private void whileLocked(Runnable change) {
    lock.lock();
    try {
      change.run();
    } finally {
      lock.unlock();
    }
  }

  boolean isClosed() {
    lock.lock();
    try {
      return closed;
    } finally {
      lock.unlock();
    }
  }

  /**
   * The real-time thread could not step the world ({@code e}, an {@link Error} too): rather than
   * leave ports that accept clients nobody serves, every client is disconnected, every port closed
   * and the world closed; then the exit handler hears {@link #EXIT_WORLD_FAILED}.
   */
  void worldThreadFailed(Throwable e) {
    log.error("the world thread failed; the simulator closes its ports and stops", e);
    lock.lock();
    try {
      if (!closed) {
        closed = true;
        for (RobotSlot s : robots.slots()) {
          s.endSession("the simulator failed");
        }
        serving.closePorts(robots.slots());
      }
    } finally {
      lock.unlock();
    }
    mapLoader.close();
    exitHandler.accept(EXIT_WORLD_FAILED);
  }

  @GuardedBy("lock")
  void requireOpen() {
    if (closed) {
      throw new IllegalStateException("the simulated world was closed; create a new one");
    }
  }

  /** Stops the real-time thread, disconnects every client, closes every TCP port. Idempotent. */
  @Override
  public void close() {
    stopRealTime();
    lock.lock();
    try {
      if (closed) {
        return;
      }
      closed = true;
      for (RobotSlot s : robots.slots()) {
        s.endSession("the simulator is shutting down");
      }
      serving.closePorts(robots.slots());
    } finally {
      lock.unlock();
    }
    mapLoader.close();
  }
}
