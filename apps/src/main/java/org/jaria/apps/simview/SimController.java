package org.jaria.apps.simview;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimObstacle;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * What the simulator view does to the world: run it in real time (times a speed-up) or pause it,
 * step it while paused, move robots and obstacles. All through {@link SimWorld}'s thread-safe API,
 * so the view never holds the world's lock while drawing.
 */
public final class SimController {

  private final SimWorld world;
  private double speedup;
  private boolean running;

  /**
   * @param speedup the starting speed (1 = real time; 0 = as fast as possible)
   */
  public SimController(SimWorld world, double speedup) {
    this.world = world;
    this.speedup = speedup;
  }

  /** The world. */
  public SimWorld world() {
    return world;
  }

  /** Whether the world runs on its own thread. */
  public synchronized boolean isRunning() {
    return running;
  }

  /** The speed-up (0 = unthrottled). */
  public synchronized double speedup() {
    return speedup;
  }

  /** Runs the world in real time times the speed-up. */
  public synchronized void run() {
    if (!running) {
      world.startRealTime(speedup);
      running = true;
    }
  }

  /** Stops the world's thread; it keeps its state and can be stepped. */
  public synchronized void pause() {
    if (running) {
      world.stopRealTime();
      running = false;
    }
  }

  /** Changes the speed (restarting the world's thread if it runs). */
  public synchronized void setSpeedup(double s) {
    speedup = s;
    if (running) {
      world.stopRealTime();
      world.startRealTime(s);
    }
  }

  /**
   * Advances a paused world by {@code millis} of simulated time (whole ticks).
   *
   * @throws IllegalStateException if the world is running
   */
  public synchronized void step(long millis) {
    if (running) {
      throw new IllegalStateException("pause the simulation before stepping it");
    }
    world.advanceMillis(millis);
  }

  /** Puts robot {@code index} at {@code pose} (its odometry keeps counting from where it was). */
  public void placeRobot(int index, ArPose pose) {
    SimRobot r = world.getRobot(index);
    r.setTruePose(pose);
  }

  /** Moves an obstacle by (dx, dy) mm; returns the obstacle in its new place. */
  public SimObstacle moveObstacle(SimObstacle o, double dx, double dy) {
    List<ArLineSegment> moved = new ArrayList<>(o.segments().size());
    for (ArLineSegment s : o.segments()) {
      moved.add(new ArLineSegment(s.x1() + dx, s.y1() + dy, s.x2() + dx, s.y2() + dy));
    }
    world.removeObstacle(o);
    return world.injectObstacle(moved);
  }

  /** Adds a box obstacle between two corners. */
  public SimObstacle addBox(double x0, double y0, double x1, double y1) {
    return world.injectBox((x0 + x1) / 2, (y0 + y1) / 2, Math.abs(x1 - x0), Math.abs(y1 - y0), 0);
  }

  /** Removes an obstacle. */
  public boolean removeObstacle(SimObstacle o) {
    return world.removeObstacle(o);
  }
}
