package org.jaria.sim.camera;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapInfoEntry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The coloured objects of a world. A map declares them as custom object types with a colour, then
 * places them with {@code Cairn:} lines, in the way MobileSim's custom types work:
 *
 * <pre>
 * MapInfo: SectorType Name=RedBall "Label=Red ball" Sim.Color=0xD02020 Sim.Shape=cylinder Sim.Diameter=200 Sim.Height=200 Sim.Obstacle=no
 * Cairn: RedBall 3000 1500 0 "" ICON "ball"
 * MapInfo: SectorType Name=RedBook Sim.Color=0xB01818 Sim.Shape=box Sim.Height=300
 * Cairn: RedBook 0 0 30 "" ICON "book" 2800 -200 3100 0
 * </pre>
 *
 * A box type takes its footprint from the Cairn's rectangle (corners x1 y1 x2 y2, turned by th
 * about their centre); a cylinder stands at the Cairn's position. {@code Sim.Obstacle=yes} also
 * makes the object solid for bumpers, sonar and laser. Objects can be added and moved at run time
 * (a test rolling a ball away from the robot).
 */
public final class ColoredObjects {

  private static final Logger log = LoggerFactory.getLogger(ColoredObjects.class);

  /**
   * Where solid objects become obstacles: the world adds an outline and returns how to take it out
   * again. An interface of this package, so that the world may hold its coloured objects without
   * this class depending on the world.
   */
  @FunctionalInterface
  public interface ObstacleSink {
    /** Adds {@code outline} as an obstacle; the returned action removes it. */
    Runnable inject(List<org.jaria.geom.ArLineSegment> outline);
  }

  private final ObstacleSink world;
  private final CopyOnWriteArrayList<ColoredObject> objects = new CopyOnWriteArrayList<>();
  private final Map<Integer, Runnable> solids = new java.util.concurrent.ConcurrentHashMap<>();
  private final AtomicInteger nextId = new AtomicInteger(1);

  /** The coloured objects of a world whose obstacles {@code world} adds and removes. */
  public ColoredObjects(ObstacleSink world) {
    this.world = world;
  }

  /** The objects now (an unmodifiable snapshot). */
  public List<ColoredObject> list() {
    return List.copyOf(objects);
  }

  /**
   * Adds an object; with {@code solid} it also blocks robots and sensors.
   *
   * @return the object with its id
   */
  public ColoredObject add(ColoredObject o, boolean solid) {
    ColoredObject withId = o.withId(nextId.getAndIncrement());
    objects.add(withId);
    if (solid) {
      solids.put(withId.id(), world.inject(outline(withId)));
    }
    return withId;
  }

  /** Moves object {@code id} (keeping it solid if it was); returns the moved object. */
  public ColoredObject move(int id, double x, double y) {
    for (int i = 0; i < objects.size(); i++) {
      ColoredObject o = objects.get(i);
      if (o.id() == id) {
        ColoredObject moved = o.at(x, y);
        objects.set(i, moved);
        Runnable solid = solids.remove(id);
        if (solid != null) {
          solid.run();
          solids.put(id, world.inject(outline(moved)));
        }
        return moved;
      }
    }
    throw new IllegalArgumentException("no coloured object with id " + id);
  }

  /** Removes object {@code id}. */
  public boolean remove(int id) {
    Runnable solid = solids.remove(id);
    if (solid != null) {
      solid.run();
    }
    return objects.removeIf(o -> o.id() == id);
  }

  /** Replaces every object with those the map declares. */
  public void replaceFromMap(ArMap map) {
    for (ColoredObject o : list()) {
      remove(o.id());
    }
    for (ArMapObject mo : map.getMapObjects()) {
      MapInfoEntry type = typeOf(map, mo.type());
      if (type == null || !type.attributes().containsKey("Sim.Color")) {
        continue;
      }
      try {
        add(
            fromMap(mo, type.attributes()),
            "yes".equalsIgnoreCase(type.attributes().getOrDefault("Sim.Obstacle", "no")));
      } catch (IllegalArgumentException e) {
        log.warn(
            "map object '{}' of type {}: {}; not shown to cameras",
            mo.name(),
            mo.type(),
            e.getMessage());
      }
    }
  }

  private static MapInfoEntry typeOf(ArMap map, String type) {
    for (MapInfoEntry e : map.getMapInfo()) {
      if (type.equals(e.getName())) {
        return e;
      }
    }
    return null;
  }

  static ColoredObject fromMap(ArMapObject mo, Map<String, String> a) {
    int rgb = parseColor(a.get("Sim.Color"));
    double height = number(a, "Sim.Height", 300);
    String shape = a.getOrDefault("Sim.Shape", "box").toLowerCase(Locale.ROOT);
    String name = mo.name().isEmpty() ? mo.type() : mo.name();
    if (shape.equals("cylinder")) {
      double d = number(a, "Sim.Diameter", 200);
      return ColoredObject.cylinder(name, mo.pose().x(), mo.pose().y(), d, height, rgb);
    }
    if (!mo.hasFromTo()) {
      double w = number(a, "Sim.Width", 300);
      return ColoredObject.box(
          name, mo.pose().x(), mo.pose().y(), mo.pose().th(), w, w, height, rgb);
    }
    double x1 = mo.fromPose().x();
    double y1 = mo.fromPose().y();
    double x2 = mo.toPose().x();
    double y2 = mo.toPose().y();
    return ColoredObject.box(
        name,
        (x1 + x2) / 2,
        (y1 + y2) / 2,
        mo.pose().th(),
        Math.abs(x2 - x1),
        Math.abs(y2 - y1),
        height,
        rgb);
  }

  private static double number(Map<String, String> a, String key, double fallback) {
    String v = a.get(key);
    if (v == null) {
      return fallback;
    }
    try {
      return Double.parseDouble(v);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(key + "=" + v + " is not a number", e);
    }
  }

  static int parseColor(String v) {
    String t = v.trim();
    if (t.startsWith("#")) {
      t = t.substring(1);
    } else if (t.startsWith("0x") || t.startsWith("0X")) {
      t = t.substring(2);
    }
    try {
      return Integer.parseInt(t, 16) & 0xFFFFFF;
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException("Sim.Color=" + v + " is not a colour like 0xRRGGBB", e);
    }
  }

  /** The object's outline as wall segments (cylinders as 16-gons). */
  static List<org.jaria.geom.ArLineSegment> outline(ColoredObject o) {
    List<org.jaria.geom.ArLineSegment> segs = new ArrayList<>();
    if (o.shape() == ColoredObject.Shape.CYLINDER) {
      int n = 16;
      double r = o.width() / 2;
      for (int i = 0; i < n; i++) {
        double a0 = 2 * Math.PI * i / n;
        double a1 = 2 * Math.PI * (i + 1) / n;
        segs.add(
            new org.jaria.geom.ArLineSegment(
                o.x() + r * Math.cos(a0), o.y() + r * Math.sin(a0),
                o.x() + r * Math.cos(a1), o.y() + r * Math.sin(a1)));
      }
      return segs;
    }
    double a = Math.toRadians(o.th());
    double cos = Math.cos(a);
    double sin = Math.sin(a);
    double[][] c = {
      {-o.width() / 2, -o.depth() / 2},
      {o.width() / 2, -o.depth() / 2},
      {o.width() / 2, o.depth() / 2},
      {-o.width() / 2, o.depth() / 2}
    };
    for (int i = 0; i < 4; i++) {
      double[] p = c[i];
      double[] q = c[(i + 1) % 4];
      segs.add(
          new org.jaria.geom.ArLineSegment(
              o.x() + cos * p[0] - sin * p[1], o.y() + sin * p[0] + cos * p[1],
              o.x() + cos * q[0] - sin * q[1], o.y() + sin * q[0] + cos * q[1]));
    }
    return segs;
  }
}
