package org.jaria.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class SegmentIndexTest {

  @Test
  void rayHitsWallAtKnownDistanceWithHeadOnIncidence() {
    SegmentIndex idx =
        SegmentIndex.builder().addSegment(1000, -500, 1000, 500, RayHit.HitKind.LINE).build();
    RayHit hit = new RayHit();
    assertTrue(idx.cast(0, 0, 1, 0, 5000, hit));
    assertEquals(1000, hit.distance, 1e-9);
    assertEquals(1, hit.cosIncidence, 1e-12);
    assertEquals(RayHit.HitKind.LINE, hit.kind);
  }

  @Test
  void rayMissesBeyondRangeAndBehind() {
    SegmentIndex idx =
        SegmentIndex.builder().addSegment(1000, -500, 1000, 500, RayHit.HitKind.LINE).build();
    RayHit hit = new RayHit();
    assertFalse(idx.cast(0, 0, 1, 0, 999, hit));
    assertFalse(idx.cast(0, 0, -1, 0, 5000, hit));
    assertFalse(idx.cast(0, 0, 0, 1, 5000, hit));
    assertFalse(hit.hit());
  }

  @Test
  void grazingRayReportsSmallIncidenceCosine() {
    SegmentIndex idx =
        SegmentIndex.builder().addSegment(0, 100, 10_000, 200, RayHit.HitKind.LINE).build();
    RayHit hit = new RayHit();
    double a = Math.toRadians(5);
    assertTrue(idx.cast(0, 0, Math.cos(a), Math.sin(a), 10_000, hit));
    assertTrue(hit.cosIncidence < 0.1, "cos " + hit.cosIncidence);
  }

  @Test
  void discsBlockRaysAtTheirRadius() {
    SegmentIndex idx = SegmentIndex.builder().addDisc(2000, 0, 10, RayHit.HitKind.POINT).build();
    RayHit hit = new RayHit();
    assertTrue(idx.cast(0, 0, 1, 0, 5000, hit));
    assertEquals(1990, hit.distance, 1e-9);
    assertEquals(RayHit.HitKind.POINT, hit.kind);
  }

  @Test
  void emptyIndexNeverHits() {
    SegmentIndex idx = SegmentIndex.builder().build();
    RayHit hit = new RayHit();
    assertFalse(idx.cast(0, 0, 1, 0, 5000, hit));
    Contact c = new Contact();
    assertFalse(idx.findContacts(new double[] {0, 1, 1}, new double[] {0, 0, 1}, 3, 0, 0, c));
  }

  /** The index must give exactly what testing every primitive gives, for any layout. */
  @Test
  void matchesBruteForceOnRandomMaps() {
    SplittableRandom rng = new SplittableRandom(42);
    for (int map = 0; map < 20; map++) {
      int n = 1 + rng.nextInt(400);
      double[][] segs = new double[n][];
      SegmentIndex.Builder b = SegmentIndex.builder();
      for (int i = 0; i < n; i++) {
        double x = rng.nextDouble(-20_000, 20_000);
        double y = rng.nextDouble(-20_000, 20_000);
        double a = rng.nextDouble(0, 2 * Math.PI);
        double len = rng.nextDouble(10, 8000);
        // Some exactly axis-aligned walls and walls on cell boundaries, as real maps have.
        if (i % 5 == 0) {
          a = 0;
        } else if (i % 7 == 0) {
          a = Math.PI / 2;
        }
        segs[i] = new double[] {x, y, x + len * Math.cos(a), y + len * Math.sin(a)};
        b.addSegment(segs[i][0], segs[i][1], segs[i][2], segs[i][3], RayHit.HitKind.LINE);
      }
      SegmentIndex idx = map % 2 == 0 ? b.build() : b.build(rng.nextDouble(150, 3000));
      RayHit hit = new RayHit();
      for (int r = 0; r < 300; r++) {
        double ox = rng.nextDouble(-25_000, 25_000);
        double oy = rng.nextDouble(-25_000, 25_000);
        double a = r % 10 == 0 ? (r % 20 == 0 ? 0 : Math.PI / 2) : rng.nextDouble(0, 2 * Math.PI);
        double dx = Math.cos(a);
        double dy = Math.sin(a);
        double range = rng.nextDouble(100, 30_000);
        double brute = Double.POSITIVE_INFINITY;
        for (double[] s : segs) {
          brute = Math.min(brute, Geometry2d.raySegment(ox, oy, dx, dy, s[0], s[1], s[2], s[3]));
        }
        hit.reset();
        idx.cast(ox, oy, dx, dy, range, hit);
        if (brute <= range) {
          assertTrue(hit.hit(), "map " + map + " ray " + r + " missed a hit at " + brute);
          assertEquals(brute, hit.distance, 1e-6, "map " + map + " ray " + r);
        } else {
          assertFalse(hit.hit(), "map " + map + " ray " + r + " hit at " + hit.distance);
        }
      }
    }
  }

  @Test
  void contactQueryFindsOverlappingWallAndNearestPoint() {
    SegmentIndex idx =
        SegmentIndex.builder()
            .addSegment(300, -1000, 300, 1000, RayHit.HitKind.LINE)
            .addSegment(5000, -1000, 5000, 1000, RayHit.HitKind.LINE)
            .build();
    Footprint f = new Footprint(400, 200, 400);
    f.place(0, 0, 0);
    Contact c = new Contact();
    assertTrue(idx.findContacts(f.x, f.y, 4, 0, 0, c));
    assertEquals(300, c.x, 1e-9);
    assertEquals(0, c.y, 1e-9);
    f.place(-200, 0, 0);
    c.reset();
    assertFalse(idx.findContacts(f.x, f.y, 4, -200, 0, c));
  }

  @Test
  void footprintsOverlapOnlyWhenTheyTouch() {
    Footprint a = new Footprint(250, 250, 400);
    Footprint b = new Footprint(250, 250, 400);
    a.place(0, 0, 0);
    b.place(600, 0, Math.toRadians(45));
    assertFalse(a.overlaps(b));
    b.place(450, 0, Math.toRadians(45));
    assertTrue(a.overlaps(b));
    assertTrue(b.overlaps(a));
  }
}
