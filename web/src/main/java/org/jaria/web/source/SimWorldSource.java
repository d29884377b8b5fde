package org.jaria.web.source;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.sim.SimLaserScan;
import org.jaria.sim.SimSnapshot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.world.WorldMap;
import org.jaria.web.model.LaserFrame;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.RobotStatus;
import org.jaria.web.model.WorldFrame;

/**
 * The simulator's world as frames: every robot's true pose, outline, sonar echoes and laser scan,
 * and the clock. A frame comes from {@link SimWorld#snapshot()}, one short copy under the world's
 * lock. A robot that software localizes can carry an {@link RobotOverlay} (its believed pose,
 * particles and path).
 */
public final class SimWorldSource implements FrameSource {

  private final SimWorld world;
  private final SimulationControl control;
  private final ArMap arMap;
  private final String mapName;
  private final Map<String, RobotOverlay> overlays = new ConcurrentHashMap<>();

  @GuardedBy("this")
  private WorldMap lastWorldMap;

  @GuardedBy("this")
  private MapLayer lastLayer;

  /**
   * @param world the world
   * @param control how it runs (its clock)
   * @param map the map file it was made from, for goals and forbidden areas (null: walls and points
   *     only, as the world keeps them)
   * @param mapName the map's name for viewers
   */
  public SimWorldSource(SimWorld world, SimulationControl control, ArMap map, String mapName) {
    this.world = world;
    this.control = control;
    this.arMap = map;
    this.mapName = mapName;
  }

  /** The world's controls (run, pause, step, speed). */
  public SimulationControl control() {
    return control;
  }

  /** Adds what software knows about robot {@code name} to its frames. */
  public void addOverlay(String name, RobotOverlay overlay) {
    overlays.put(name, overlay);
  }

  @Override
  // Identity on purpose: the world holds a new WorldMap exactly when a map is loaded, and comparing
  // the contents of two maps on every frame would cost far more.
  @SuppressWarnings("ReferenceEquality")
  public synchronized MapLayer map() {
    WorldMap now = world.getMap();
    if (lastLayer == null || now != lastWorldMap) {
      // The map file's goals and areas hold for the map the world started with; a map a client
      // loaded later (SIM_CTRL) shows its walls and points.
      lastLayer =
          lastLayer == null && arMap != null ? MapLayers.of(arMap, mapName) : MapLayers.of(now);
      lastWorldMap = now;
    }
    return lastLayer;
  }

  @Override
  public WorldFrame frame() {
    SimSnapshot s = world.snapshot();
    List<RobotFrame> robots = new ArrayList<>(s.robots().size());
    for (SimSnapshot.RobotView v : s.robots()) {
      RobotFrame base = robot(v);
      RobotOverlay o = overlays.get(v.name());
      robots.add(o == null ? base : o.apply(base));
    }
    return new WorldFrame(control.clock(), robots);
  }

  /** One robot of a snapshot as a frame. */
  static RobotFrame robot(SimSnapshot.RobotView v) {
    Points.Builder origins = Points.builder(v.sonar().size());
    Points.Builder echoes = Points.builder(v.sonar().size());
    for (SimSnapshot.SonarView s : v.sonar()) {
      if (s.echo() && s.rangeMm() > 0) {
        double th = Math.toRadians(s.thDeg());
        origins.add(s.x(), s.y());
        echoes.add(s.x() + s.rangeMm() * Math.cos(th), s.y() + s.rangeMm() * Math.sin(th));
      }
    }
    Points.Builder outline = Points.builder(v.footprint().size());
    for (ArPose c : v.footprint()) {
      outline.add(c.x(), c.y());
    }
    SimLaserScan l = v.laser();
    LaserFrame laser =
        l == null ? null : new LaserFrame(l.origin(), l.startDeg(), l.incrementDeg(), l.ranges());
    RobotStatus status =
        new RobotStatus(
            v.vel(),
            v.rotVel(),
            Double.NaN,
            v.motorsEnabled(),
            v.stallAndBumpers() != 0,
            v.sessionOpen() ? "client connected" : v.clientConnected() ? "connecting" : "no client",
            Double.NaN);
    return new RobotFrame(
        v.name(),
        v.subtype(),
        v.truePose(),
        null,
        outline.build(),
        origins.build(),
        echoes.build(),
        laser,
        Points.EMPTY,
        Points.EMPTY,
        null,
        status);
  }
}
