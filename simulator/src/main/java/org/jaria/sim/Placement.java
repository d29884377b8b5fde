package org.jaria.sim;

import org.jaria.geom.ArPose;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.world.Contact;
import org.jaria.sim.world.Footprint;
import org.jaria.sim.world.WorldGeometry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Finds where a new robot can stand: the start pose if free, else the nearest free spot. */
final class Placement {

  private static final Logger log = LoggerFactory.getLogger(Placement.class);

  private static final int MAX_RING = 10;

  private Placement() {}

  /**
   * Moves every robot to a free spot near {@code home} (after a map change) and makes that its
   * SIM_RESET position. The robots are first put far away so that they do not block each other's
   * old places.
   */
  static void replaceAll(java.util.List<RobotSlot> slots, ArPose home, WorldGeometry world) {
    for (RobotSlot s : slots) {
      s.body.setTruePose(new ArPose(1e9 + s.body.index() * 1e4, 1e9, 0));
    }
    world.robotsMoved();
    for (RobotSlot s : slots) {
      ArPose p = freeSpot(home, s.body.model(), world);
      s.body.setTruePose(p);
      s.body.setStartPose(p);
    }
  }

  /**
   * The start pose {@code home} if a robot of {@code model} standing there touches nothing, else
   * the nearest free spot on a grid of robot-sized steps around it (same heading); {@code home}
   * itself if no spot is free.
   */
  static ArPose freeSpot(ArPose home, RobotModel model, WorldGeometry world) {
    Footprint f = new Footprint(model.getLengthFront(), model.getLengthRear(), model.getWidth());
    Contact c = new Contact();
    double step = 2 * Math.max(model.getRadius(), f.boundingRadius()) + 100;
    double th = Math.toRadians(home.th());
    double cos = Math.cos(th);
    double sin = Math.sin(th);
    for (int ring = 0; ring <= MAX_RING; ring++) {
      for (int i = -ring; i <= ring; i++) {
        for (int j = -ring; j <= ring; j++) {
          if (Math.max(Math.abs(i), Math.abs(j)) != ring) {
            continue;
          }
          // Prefer spots beside and behind the start over spots ahead of it.
          double lx = -i * step;
          double ly = j * step;
          double x = home.x() + cos * lx - sin * ly;
          double y = home.y() + sin * lx + cos * ly;
          f.place(x, y, th);
          if (!world.collides(f, -1, c)) {
            return new ArPose(x, y, home.th());
          }
        }
      }
    }
    log.warn("no free spot for a {} near {}; placing it there anyway", model.getSubtype(), home);
    return home;
  }
}
