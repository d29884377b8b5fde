package org.jaria.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The robot grid gives exactly what testing every robot gives, also after robots were removed; a
 * removed robot is seen by nothing.
 */
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
      g.addRobot(i, f);
    }
    g.setSolid(7, false);
    java.util.Set<Integer> removed = new java.util.HashSet<>(java.util.List.of(5, 6, 59));
    for (int i = 30; i < 40; i++) {
      removed.add(i);
    }
    for (int r : removed) {
      assertTrue(g.removeRobot(r));
    }
    assertEquals(60 - removed.size(), g.robotCount());
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
      assertTrue(!removed.contains(a.robot), "ray " + k + " met removed robot " + a.robot);
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
      assertTrue(!removed.contains(ca.robot), "probe " + k + " touched removed robot " + ca.robot);
      touches += x ? 1 : 0;
    }
    assertTrue(touches > 10, "some probes touched robots: " + touches);
  }

  @Test
  void aRemovedRobotNoLongerStopsRaysOrBlocksAndItsNumberStaysItsOwn() {
    WorldGeometry g = new WorldGeometry();
    g.setStatics(
        SegmentIndex.builder().addSegment(5000, -1000, 5000, 1000, RayHit.HitKind.LINE).build());
    Footprint a = new Footprint(200, 200, 400);
    a.place(0, 0, 0);
    Footprint b = new Footprint(200, 200, 400);
    b.place(2000, 0, 0);
    g.addRobot(3, a);
    g.addRobot(8, b);
    RayHit hit = new RayHit();
    g.cast(0, 0, 1, 0, 10_000, 3, hit);
    assertEquals(RayHit.HitKind.ROBOT, hit.kind);
    assertEquals(8, hit.robot);
    assertEquals(1800, hit.distance, 1e-6);
    Footprint probe = new Footprint(200, 200, 400);
    probe.place(2100, 0, 0);
    Contact c = new Contact();
    assertTrue(g.collides(probe, -1, c));
    assertEquals(8, c.robot);

    assertTrue(g.removeRobot(8));
    assertFalse(g.removeRobot(8), "removed once only");
    g.cast(0, 0, 1, 0, 10_000, 3, hit);
    assertEquals(RayHit.HitKind.LINE, hit.kind, "the ray now reaches the wall");
    assertEquals(5000, hit.distance, 1e-6);
    assertFalse(g.collides(probe, -1, c), "the place is free");
    assertThrows(IllegalArgumentException.class, () -> g.addRobot(3, probe));
    g.setSolid(8, false); // a removed number: nothing happens
    g.cast(4000, 0, -1, 0, 10_000, -1, hit);
    assertEquals(3, hit.robot, "robot 3 keeps its number");
  }
}
