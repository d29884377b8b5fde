package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import org.jaria.geom.ArPose;
import org.jaria.web.model.Points;

/**
 * Writes {@code foxglove.SceneUpdate} entities: an entity with every field Foxglove's schema
 * requires (empty lists where this server draws nothing of a kind), and line, arrow and text
 * primitives in the map frame.
 */
final class SceneWriter {

  /** Foxglove's LINE_STRIP, LINE_LOOP and LINE_LIST. */
  static final int LINE_STRIP = 0;

  static final int LINE_LOOP = 1;
  static final int LINE_LIST = 2;

  private final JsonGenerator g;
  private final long t;

  SceneWriter(JsonGenerator g, long t) {
    this.g = g;
    this.t = t;
  }

  /** Starts the update: no deletions, then the entity list. */
  void begin() throws IOException {
    g.writeStartObject();
    g.writeArrayFieldStart("deletions");
    g.writeEndArray();
    g.writeArrayFieldStart("entities");
  }

  void end() throws IOException {
    g.writeEndArray();
    g.writeEndObject();
  }

  /**
   * Starts an entity; its primitive lists follow, in the schema's order, then {@link #endEntity}.
   */
  void beginEntity(String id) throws IOException {
    g.writeStartObject();
    Encoding.time(g, "timestamp", t);
    g.writeStringField("frame_id", Encoding.MAP_FRAME);
    g.writeStringField("id", id);
    g.writeObjectFieldStart("lifetime");
    g.writeNumberField("sec", 0);
    g.writeNumberField("nsec", 0);
    g.writeEndObject();
    g.writeBooleanField("frame_locked", false);
    g.writeArrayFieldStart("metadata");
    g.writeEndArray();
  }

  void endEntity() throws IOException {
    g.writeEndObject();
  }

  /** Writes the empty lists named, e.g. {@code empty("cubes", "spheres")}. */
  void empty(String... lists) throws IOException {
    for (String l : lists) {
      g.writeArrayFieldStart(l);
      g.writeEndArray();
    }
  }

  void beginList(String name) throws IOException {
    g.writeArrayFieldStart(name);
  }

  void endList() throws IOException {
    g.writeEndArray();
  }

  /** One line primitive through {@code pts} (mm). */
  void line(int type, Points pts, double thicknessM, int rgb, double alpha) throws IOException {
    g.writeStartObject();
    g.writeNumberField("type", type);
    Encoding.pose(g, "pose", ArPose.ORIGIN);
    g.writeNumberField("thickness", thicknessM);
    g.writeBooleanField("scale_invariant", false);
    g.writeArrayFieldStart("points");
    for (int i = 0; i < pts.size(); i++) {
      g.writeStartObject();
      g.writeNumberField("x", Encoding.metres(pts.x(i)));
      g.writeNumberField("y", Encoding.metres(pts.y(i)));
      g.writeNumberField("z", 0);
      g.writeEndObject();
    }
    g.writeEndArray();
    Encoding.color(g, "color", rgb, alpha);
    g.writeArrayFieldStart("colors");
    g.writeEndArray();
    g.writeArrayFieldStart("indices");
    g.writeEndArray();
    g.writeEndObject();
  }

  /** One arrow primitive at {@code p}, pointing along its heading. */
  void arrow(ArPose p, double lengthM, int rgb) throws IOException {
    g.writeStartObject();
    Encoding.pose(g, "pose", p);
    g.writeNumberField("shaft_length", lengthM * 0.7);
    g.writeNumberField("shaft_diameter", lengthM * 0.12);
    g.writeNumberField("head_length", lengthM * 0.3);
    g.writeNumberField("head_diameter", lengthM * 0.3);
    Encoding.color(g, "color", rgb, 1);
    g.writeEndObject();
  }

  /** One text primitive at {@code p} that faces the viewer. */
  void text(ArPose p, String text, int rgb) throws IOException {
    g.writeStartObject();
    Encoding.pose(g, "pose", p);
    g.writeBooleanField("billboard", true);
    g.writeNumberField("font_size", 12);
    g.writeBooleanField("scale_invariant", true);
    Encoding.color(g, "color", rgb, 1);
    g.writeStringField("text", text);
    g.writeEndObject();
  }
}
