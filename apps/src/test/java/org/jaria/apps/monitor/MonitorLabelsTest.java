package org.jaria.apps.monitor;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.jaria.apps.fx.LabelPlacer;
import org.jaria.apps.fx.Viewport;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

/** The monitor's names on the office map, fitted to its map pane as the monitor opens it. */
class MonitorLabelsTest {

  @Test
  void theDockAtTheMapsEdgeShowsItsWholeName() {
    ArMap m = ArMap.loadBundled("office");
    Viewport vp = new Viewport();
    vp.setSize(880, 745); // the map pane of a 1280 x 800 window
    vp.fit(m.getMinPos().x(), m.getMinPos().y(), m.getMaxPos().x(), m.getMaxPos().y(), 20);
    List<LabelPlacer.Placed> placed =
        MonitorRenderer.placeLabels(m.getMapObjects(), m.getLines(), vp, t -> 7.0 * t.length(), 14);
    Optional<LabelPlacer.Placed> dock =
        placed.stream()
            .filter(p -> ((ArMapObject) p.label().tag()).type().equalsIgnoreCase("Dock"))
            .findFirst();
    assertTrue(dock.isPresent(), "the dock's name is shown: " + placed);
    // Not across the map's east wall, where it looked cut off at the map's edge.
    LabelPlacer.Placed d = dock.get();
    double wall = vp.toScreenX(m.getMaxPos().x());
    assertTrue(d.right() < wall, "inside the map: " + d + ", wall at " + wall);
    for (LabelPlacer.Placed p : placed) {
      assertTrue(
          p.left() >= 0 && p.top() >= 0 && p.right() <= vp.width() && p.bottom() <= vp.height(),
          "inside the picture: " + p);
    }
    long goals = m.getMapObjects().stream().filter(o -> !o.name().isEmpty()).count();
    assertTrue(placed.size() == goals, placed.size() + " of " + goals + " names shown");
  }
}
