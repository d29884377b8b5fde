package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.web.model.RobotFrame;

/** Every robot as a {@code foxglove.SceneUpdate} entity: its outline and a heading arrow. */
final class RobotScene {

  static final int BODY = 0xc0392b;
  static final int BELIEVED = 0x2c6fbb;

  private RobotScene() {}

  static void write(JsonGenerator g, long t, List<RobotFrame> robots) throws IOException {
    SceneWriter s = new SceneWriter(g, t);
    s.begin();
    for (RobotFrame r : robots) {
      ArPose p = r.shownPose();
      s.beginEntity("robot/" + r.name());
      s.beginList("arrows");
      if (p != null) {
        s.arrow(p, 0.45, BODY);
      }
      if (r.believedPose() != null && r.truePose() != null) {
        s.arrow(r.believedPose(), 0.35, BELIEVED);
      }
      s.endList();
      s.empty("cubes", "spheres", "cylinders");
      s.beginList("lines");
      if (r.footprint().size() > 2) {
        s.line(SceneWriter.LINE_LOOP, r.footprint(), 0.03, BODY, 1);
      }
      s.endList();
      s.empty("triangles");
      s.beginList("texts");
      if (p != null) {
        s.text(new ArPose(p.x(), p.y() + 400, 0), r.name(), BODY);
      }
      s.endList();
      s.empty("models");
      s.endEntity();
    }
    s.end();
  }
}
