package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.apps.fx.LabelPlacer;
import org.jaria.apps.fx.Viewport;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

/** The editor's names on the README's map, fitted as the editor opens it. */
class MapRendererLabelsTest {

  @Test
  void columbiasNamesCoverNoMarkerNoOtherNameAndStayInThePicture() {
    ArMap m = ArMap.loadBundled("columbia");
    AtomicLong ids = new AtomicLong(1);
    List<MapObjectEntry> objects = MapFile.wrap(m, ids::getAndIncrement).content().objects();
    Viewport vp = new Viewport();
    vp.setSize(1070, 600); // the map pane of a 1280 x 800 window
    vp.fit(
        m.getLineMinPos().x(),
        m.getLineMinPos().y(),
        m.getLineMaxPos().x(),
        m.getLineMaxPos().y(),
        24);
    List<LabelPlacer.Placed> placed =
        MapRenderer.placeLabels(
            objects,
            MapFile.wrap(m, ids::getAndIncrement).content().lines(),
            null,
            vp,
            t -> 7.0 * t.length(),
            14);
    List<double[]> markers = new ArrayList<>();
    int named = 0;
    for (ArMapObject o : m.getMapObjects()) {
      if (!o.hasFromTo()) {
        double x = vp.toScreenX(o.pose().x());
        double y = vp.toScreenY(o.pose().y());
        double r = LabelPlacer.MARKER;
        markers.add(new double[] {x - r, y - r, x + r, y + r});
        named += o.name().isEmpty() ? 0 : 1;
      }
    }
    assertTrue(named > 5, "columbia has named goals: " + named);
    assertTrue(placed.size() >= named - 2, placed.size() + " of " + named + " shown");
    for (int i = 0; i < placed.size(); i++) {
      LabelPlacer.Placed p = placed.get(i);
      double[] r = {p.left(), p.top(), p.right(), p.bottom()};
      assertTrue(r[0] >= 0 && r[1] >= 0 && r[2] <= vp.width() && r[3] <= vp.height(), "" + p);
      for (double[] mk : markers) {
        assertFalse(LabelPlacer.overlaps(mk, r), p + " covers a marker");
      }
      for (int j = i + 1; j < placed.size(); j++) {
        LabelPlacer.Placed q = placed.get(j);
        assertFalse(
            LabelPlacer.overlaps(r, new double[] {q.left(), q.top(), q.right(), q.bottom()}),
            p + " overlaps " + q);
      }
    }
    assertEquals(placed.size(), placed.stream().map(p -> p.label().text()).distinct().count());
  }
}
