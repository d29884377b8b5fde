package org.jaria.sim;

import java.util.List;
import org.jaria.clock.VirtualClock;
import org.jaria.sim.world.WorldGeometry;

/**
 * One tick of a world, in the order every tick runs: a map a client asked for is applied, new TCP
 * clients are attached, every session reads and executes what its client sent, every robot moves
 * and senses, every session sends what is due, and robot-factory robots whose client left are taken
 * out. Counts the ticks. Runs under the world's lock ({@link SimWorld#step()} holds it).
 */
final class WorldTick {

  private final SimWorld world;
  private final VirtualClock clock;
  private final long tickNanos;
  private final WorldStatics statics;
  private final WorldGeometry geometry;
  private final WorldServing serving;
  private final WorldRobots robots;
  private long steps;

  WorldTick(
      SimWorld world,
      VirtualClock clock,
      long tickNanos,
      WorldStatics statics,
      WorldGeometry geometry,
      WorldServing serving,
      WorldRobots robots) {
    this.world = world;
    this.clock = clock;
    this.tickNanos = tickNanos;
    this.statics = statics;
    this.geometry = geometry;
    this.serving = serving;
    this.robots = robots;
  }

  /** Runs one tick; stops early if a client's command closed the world. */
  void run() {
    long now = clock.nanoTime();
    ClientMapLoader.Result loaded = world.mapLoader().poll();
    if (loaded != null) {
      world.host().mapLoadFinished(loaded);
    }
    statics.rebuild();
    serving.acceptPending(clock, robots);
    List<RobotSlot> slots = robots.slots();
    for (RobotSlot s : slots) {
      s.poll(now);
      if (world.isClosed()) {
        return;
      }
    }
    long after = now + tickNanos;
    double dt = tickNanos / 1e9;
    // a robot can only meet robots it can reach within this tick
    geometry.indexRobots(robots.maxSpeed() * dt + 1);
    for (RobotSlot s : slots) {
      s.body.physics(dt, geometry, after);
    }
    clock.advanceTo(after);
    for (RobotSlot s : slots) {
      s.afterPhysics(after);
    }
    robots.removeOrphans();
    steps++;
  }

  /** Whole ticks needed to cover {@code nanos} (rounded up). */
  long ticksFor(long nanos) {
    return (nanos + tickNanos - 1) / tickNanos;
  }

  /** Ticks run so far. */
  long steps() {
    return steps;
  }
}
