package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import org.jaria.geom.ArPose;
import org.jaria.web.model.MapLayer;

/**
 * The map as a {@code foxglove.SceneUpdate}: walls as one line list, the sensor points as short
 * crosses, forbidden lines and areas in red, goals as arrows with their names.
 */
final class MapScene {

  static final int WALL = 0x202830;
  static final int POINT = 0x4a5866;
  static final int FORBIDDEN = 0xd03030;
  static final int GOAL = 0x1f8f4a;

  private MapScene() {}

  static void write(JsonGenerator g, long t, MapLayer map) throws IOException {
    SceneWriter s = new SceneWriter(g, t);
    s.begin();
    s.beginEntity("map");
    s.empty("arrows", "cubes", "spheres", "cylinders");
    s.beginList("lines");
    if (map.lines().size() > 0) {
      s.line(SceneWriter.LINE_LIST, map.lines(), 0.03, WALL, 1);
    }
    if (map.points().size() > 0) {
      s.line(SceneWriter.LINE_LIST, crosses(map), 0.01, POINT, 1);
    }
    if (map.forbiddenLines().size() > 0) {
      s.line(SceneWriter.LINE_LIST, map.forbiddenLines(), 0.05, FORBIDDEN, 1);
    }
    for (var area : map.forbiddenAreas()) {
      s.line(SceneWriter.LINE_LOOP, area, 0.04, FORBIDDEN, 0.9);
    }
    s.endList();
    s.empty("triangles", "texts", "models");
    s.endEntity();
    s.beginEntity("goals");
    s.beginList("arrows");
    for (MapLayer.Goal goal : map.goals()) {
      s.arrow(new ArPose(goal.x(), goal.y(), goal.hasHeading() ? goal.thDeg() : 0), 0.4, GOAL);
    }
    s.endList();
    s.empty("cubes", "spheres", "cylinders", "lines", "triangles");
    s.beginList("texts");
    for (MapLayer.Goal goal : map.goals()) {
      s.text(new ArPose(goal.x(), goal.y() + 250, 0), goal.name(), GOAL);
    }
    s.endList();
    s.empty("models");
    s.endEntity();
    s.end();
  }

  /** Each sensor point as a small cross (two 40 mm segments), so Foxglove shows it. */
  private static org.jaria.web.model.Points crosses(MapLayer map) {
    var b = org.jaria.web.model.Points.builder(4 * map.points().size());
    for (int i = 0; i < map.points().size(); i++) {
      float x = map.points().x(i);
      float y = map.points().y(i);
      b.add(x - 20, y).add(x + 20, y).add(x, y - 20).add(x, y + 20);
    }
    return b.build();
  }
}
