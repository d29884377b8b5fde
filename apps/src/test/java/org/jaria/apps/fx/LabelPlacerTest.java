package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Names never overlap each other or a marker, and never reach past the picture's edge. */
class LabelPlacerTest {

  static double[] rect(LabelPlacer.Placed p) {
    LabelPlacer.Label l = p.label();
    return new double[] {p.left(), p.top(), p.left() + l.width(), p.top() + l.height()};
  }

  static void assertNoOverlaps(List<LabelPlacer.Placed> placed) {
    for (int i = 0; i < placed.size(); i++) {
      for (int j = i + 1; j < placed.size(); j++) {
        assertFalse(
            LabelPlacer.overlaps(rect(placed.get(i)), rect(placed.get(j))),
            placed.get(i) + " overlaps " + placed.get(j));
      }
    }
  }

  @Test
  void twoCloseGoalsPutTheirNamesOnDifferentSides() {
    List<LabelPlacer.Placed> p =
        LabelPlacer.place(
            List.of(
                new LabelPlacer.Label(100, 100, 60, 14, "Door 1"),
                new LabelPlacer.Label(115, 100, 60, 14, "Door 2")));
    assertEquals(2, p.size(), "both fit: " + p);
    assertNoOverlaps(p);
    assertTrue(p.get(0).left() < 100 || p.get(0).centerY() != 100, "the first moved aside");
  }

  @Test
  void aCrowdedSpotShowsWhatFitsAndLeavesTheRestOut() {
    List<LabelPlacer.Label> crowd = new ArrayList<>();
    for (int i = 0; i < 10; i++) {
      crowd.add(new LabelPlacer.Label(200 + i, 200, 80, 14, "Goal " + i));
    }
    List<LabelPlacer.Placed> p = LabelPlacer.place(crowd);
    assertTrue(p.size() < 10 && !p.isEmpty(), "some, not all: " + p.size());
    assertNoOverlaps(p);
    assertEquals("Goal 0", p.get(0).label().text(), "the first listed is placed first");
  }

  @Test
  void aNameAtThePicturesRightEdgeGoesToTheLeftOfItsMarker() {
    List<LabelPlacer.Placed> p =
        LabelPlacer.place(
            List.of(new LabelPlacer.Label(870, 300, 40, 14, "Dock")),
            new double[0],
            new double[0],
            880,
            700);
    assertEquals(1, p.size());
    assertTrue(p.get(0).right() <= 880 && p.get(0).right() < 870, "left of it: " + p.get(0));
  }

  @Test
  void aNameAtATopCornerStaysInside() {
    List<LabelPlacer.Placed> p =
        LabelPlacer.place(
            List.of(new LabelPlacer.Label(875, 3, 40, 14, "Corner")),
            new double[0],
            new double[0],
            880,
            700);
    assertEquals(1, p.size());
    LabelPlacer.Placed c = p.get(0);
    assertTrue(c.left() >= 0 && c.top() >= 0 && c.right() <= 880 && c.bottom() <= 700, "" + c);
  }

  @Test
  void noNameCoversAMarkerThatHasNone() {
    // A home without a name just right of a goal: the goal's name goes elsewhere.
    List<LabelPlacer.Placed> p =
        LabelPlacer.place(
            List.of(new LabelPlacer.Label(100, 100, 50, 14, "Goal")),
            new double[] {125, 100},
            new double[0],
            1000,
            1000);
    assertEquals(1, p.size());
    double[] home = {118, 93, 132, 107};
    assertFalse(LabelPlacer.overlaps(home, rect(p.get(0))), "" + p.get(0));
  }

  /** A dock just inside the map's outer wall: its name goes inside, not across the wall. */
  @Test
  void aSideThatCrossesNoWallIsPreferred() {
    double[] eastWall = {860, 0, 860, 700};
    List<LabelPlacer.Placed> p =
        LabelPlacer.place(
            List.of(new LabelPlacer.Label(840, 420, 28, 14, "Dock")),
            new double[0],
            eastWall,
            880,
            700);
    assertEquals(1, p.size());
    assertTrue(p.get(0).right() < 840, "left of its marker, inside the map: " + p.get(0));
    // With walls on every side, the first free side is still used rather than no name.
    double[] box = {820, 400, 860, 400, 860, 400, 860, 440, 860, 440, 820, 440, 820, 440, 820, 400};
    double[] tight = {800, 380, 880, 380, 880, 460, 800, 460};
    List<LabelPlacer.Placed> q =
        LabelPlacer.place(
            List.of(new LabelPlacer.Label(840, 420, 28, 14, "Dock")),
            new double[0],
            concat(box, tight),
            880,
            700);
    assertEquals(1, q.size(), "shown even so");
  }

  @Test
  void segmentsCrossARectangleOnlyWhereTheyPassThroughIt() {
    double[] r = {10, 10, 20, 20};
    assertTrue(LabelPlacer.crosses(0, 15, 30, 15, r), "straight through");
    assertTrue(LabelPlacer.crosses(15, 15, 40, 40, r), "from inside");
    assertFalse(LabelPlacer.crosses(0, 0, 30, 5, r), "below it");
    assertFalse(LabelPlacer.crosses(25, 0, 25, 30, r), "beside it");
    assertTrue(LabelPlacer.crosses(0, 30, 30, 0, r), "diagonally across");
  }

  private static double[] concat(double[] a, double[] b) {
    double[] c = java.util.Arrays.copyOf(a, a.length + b.length);
    System.arraycopy(b, 0, c, a.length, b.length);
    return c;
  }
}
