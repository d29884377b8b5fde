package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import org.jaria.geom.ArPose;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;

/**
 * The map as a {@code foxglove.SceneUpdate} of four entities: {@code walls} (one line list), {@code
 * points} (the sensor points as short crosses), {@code forbidden} (forbidden lines and areas, red)
 * and {@code goals} (arrows with their names).
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
    lines(s, "walls", map.lines(), 0.03, WALL);
    lines(s, "points", crosses(map), 0.01, POINT);
    s.beginEntity("forbidden");
    s.empty("arrows", "cubes", "spheres", "cylinders");
    s.beginList("lines");
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
      s.text(new ArPose(goal.x(), goal.y(), 0), goal.name(), GOAL);
    }
    s.endList();
    s.empty("models");
    s.endEntity();
    s.end();
  }

  /** An entity of one line list (nothing if there are no points). */
  private static void lines(SceneWriter s, String id, Points pts, double thickness, int rgb)
      throws IOException {
    s.beginEntity(id);
    s.empty("arrows", "cubes", "spheres", "cylinders");
    s.beginList("lines");
    if (pts.size() > 0) {
      s.line(SceneWriter.LINE_LIST, pts, thickness, rgb, 1);
    }
    s.endList();
    s.empty("triangles", "texts", "models");
    s.endEntity();
  }

  /** Each sensor point as a small cross (two 40 mm segments), so Foxglove shows it. */
  private static Points crosses(MapLayer map) {
    var b = Points.builder(4 * map.points().size());
    for (int i = 0; i < map.points().size(); i++) {
      float x = map.points().x(i);
      float y = map.points().y(i);
      b.add(x - 20, y).add(x + 20, y).add(x, y - 20).add(x, y + 20);
    }
    return b.build();
  }
}
