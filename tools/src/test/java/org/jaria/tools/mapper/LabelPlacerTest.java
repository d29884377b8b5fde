package org.jaria.tools.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.tools.fx.Viewport;
import org.junit.jupiter.api.Test;

/** Goal names never overlap each other or another goal's marker. */
class LabelPlacerTest {

  private static double[] rect(LabelPlacer.Placed p) {
    LabelPlacer.Label l = p.label();
    return new double[] {p.left(), p.top(), p.left() + l.width(), p.top() + l.height()};
  }

  private static void assertNoOverlaps(List<LabelPlacer.Placed> placed) {
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

  /** The README's map, fitted to a 1280×800 window as the editor opens it. */
  @Test
  void columbiasGoalNamesDoNotOverlapWhenTheMapIsFitted() {
    ArMap m = ArMap.loadBundled("columbia");
    Viewport vp = new Viewport();
    vp.setSize(1280, 800);
    vp.fit(
        m.getLineMinPos().x(),
        m.getLineMinPos().y(),
        m.getLineMaxPos().x(),
        m.getLineMaxPos().y(),
        24);
    List<LabelPlacer.Label> labels = new ArrayList<>();
    for (ArMapObject o : m.getMapObjects()) {
      if (!o.name().isEmpty() && !o.hasFromTo()) {
        labels.add(
            new LabelPlacer.Label(
                vp.toScreenX(o.pose().x()),
                vp.toScreenY(o.pose().y()),
                7.0 * o.name().length(),
                14,
                o.name()));
      }
    }
    List<LabelPlacer.Placed> p = LabelPlacer.place(labels);
    assertTrue(labels.size() > 5, "columbia has named goals: " + labels.size());
    assertTrue(p.size() >= labels.size() / 2, p.size() + " of " + labels.size() + " shown");
    assertNoOverlaps(p);
  }
}
