package org.jaria.sim;

import java.util.ArrayList;
import java.util.List;
import org.jaria.sim.world.RayHit;
import org.jaria.sim.world.WorldGeometry;

/**
 * Questions about a world's ground truth that tests, tools and sensors ask: how far a ray goes, a
 * consistent picture of every robot and obstacle, how many clients are connected. Runs under the
 * world's lock.
 */
final class WorldQueries {

  private final WorldStatics statics;
  private final WorldGeometry geometry;

  WorldQueries(WorldStatics statics, WorldGeometry geometry) {
    this.statics = statics;
    this.geometry = geometry;
  }

  /** Distance along the ray to the nearest solid thing, ignoring robot {@code self} (−1: none). */
  double castRay(double x, double y, double thDeg, double maxRange, int self) {
    statics.rebuild();
    double r = Math.toRadians(thDeg);
    RayHit hit = new RayHit();
    geometry.cast(x, y, Math.cos(r), Math.sin(r), maxRange, self, hit);
    return hit.distance;
  }

  SimSnapshot snapshot(long timeNanos, List<RobotSlot> slots) {
    List<SimSnapshot.RobotView> views = new ArrayList<>(slots.size());
    for (RobotSlot s : slots) {
      views.add(Views.robot(s));
    }
    return new SimSnapshot(timeNanos, views, statics.list());
  }

  int connectedClientCount(List<RobotSlot> slots) {
    int n = 0;
    for (RobotSlot s : slots) {
      if (s.clients.hasConnections()) {
        n++;
      }
    }
    return n;
  }

  /** What the robots' ports did with their clients so far (robots that left not counted). */
  ServerCounters serverCounters(List<RobotSlot> slots) {
    long sessions = 0;
    long refused = 0;
    long timedOut = 0;
    long replaced = 0;
    for (RobotSlot s : slots) {
      sessions += s.clients.connections();
      refused += s.clients.refused();
      timedOut += s.clients.timedOut();
      replaced += s.clients.replaced();
    }
    return new ServerCounters(sessions, refused, timedOut, replaced);
  }
}
