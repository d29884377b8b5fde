package org.jaria.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The robot grid gives exactly what testing every robot gives. */
class WorldGeometryTest {

  @Test
  void robotGridMatchesTestingEveryRobot() {
    SplittableRandom rng = new SplittableRandom(9);
    WorldGeometry g = new WorldGeometry();
    g.setStatics(
        SegmentIndex.builder()
            .addSegment(-30_000, 20_000, 30_000, 20_000, RayHit.HitKind.LINE)
            .build());
    for (int i = 0; i < 60; i++) {
      Footprint f =
          new Footprint(
              200 + rng.nextDouble(200), 200 + rng.nextDouble(200), 300 + rng.nextDouble(300));
      f.place(
          rng.nextDouble(-15_000, 15_000), rng.nextDouble(-15_000, 15_000), rng.nextDouble(0, 6.3));
      g.addRobot(f);
    }
    g.setSolid(7, false);
    RayHit a = new RayHit();
    RayHit b = new RayHit();
    int hits = 0;
    for (int k = 0; k < 5000; k++) {
      double ox = rng.nextDouble(-20_000, 20_000);
      double oy = rng.nextDouble(-20_000, 20_000);
      double th = rng.nextDouble(0, 2 * Math.PI);
      double range = rng.nextDouble(100, 40_000);
      int ignore = rng.nextInt(-1, 60);
      g.indexRobots(0);
      g.cast(ox, oy, Math.cos(th), Math.sin(th), range, ignore, a);
      g.robotsMoved();
      g.cast(ox, oy, Math.cos(th), Math.sin(th), range, ignore, b);
      assertEquals(b.distance, a.distance, 1e-9, "ray " + k);
      assertEquals(b.robot, a.robot, "ray " + k);
      hits += a.kind == RayHit.HitKind.ROBOT ? 1 : 0;
    }
    assertTrue(hits > 100, "the rays met robots: " + hits);
    Contact ca = new Contact();
    Contact cb = new Contact();
    Footprint probe = new Footprint(300, 300, 500);
    int touches = 0;
    for (int k = 0; k < 3000; k++) {
      probe.place(
          rng.nextDouble(-15_000, 15_000), rng.nextDouble(-15_000, 15_000), rng.nextDouble(0, 6.3));
      g.indexRobots(0);
      boolean x = g.collides(probe, -1, ca);
      g.robotsMoved();
      boolean y = g.collides(probe, -1, cb);
      assertEquals(y, x);
      assertEquals(cb.robot, ca.robot);
      touches += x ? 1 : 0;
    }
    assertTrue(touches > 10, "some probes touched robots: " + touches);
  }
}
