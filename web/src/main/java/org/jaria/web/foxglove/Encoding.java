package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import org.jaria.geom.ArPose;

/**
 * The pieces every Foxglove message shares, written in Foxglove's units: metres, radians, and
 * orientation as a quaternion about z. JAria's own units (millimetres, degrees) end here.
 */
final class Encoding {

  /** The fixed frame every position is in. */
  static final String MAP_FRAME = "map";

  private Encoding() {}

  /** Millimetres to metres, rounded to a tenth of a millimetre (shorter JSON, nothing lost). */
  static double metres(double mm) {
    return Math.round(mm * 10.0) / 10000.0;
  }

  static void time(JsonGenerator g, String field, long nanos) throws IOException {
    long t = Math.max(0, nanos);
    g.writeObjectFieldStart(field);
    g.writeNumberField("sec", t / 1_000_000_000L);
    g.writeNumberField("nsec", t % 1_000_000_000L);
    g.writeEndObject();
  }

  static void vector(JsonGenerator g, String field, double xMm, double yMm) throws IOException {
    g.writeObjectFieldStart(field);
    g.writeNumberField("x", metres(xMm));
    g.writeNumberField("y", metres(yMm));
    g.writeNumberField("z", 0);
    g.writeEndObject();
  }

  /** A rotation of {@code thDeg} about z as a quaternion. */
  static void quaternion(JsonGenerator g, String field, double thDeg) throws IOException {
    double half = Math.toRadians(thDeg) / 2;
    g.writeObjectFieldStart(field);
    g.writeNumberField("x", 0);
    g.writeNumberField("y", 0);
    g.writeNumberField("z", round(Math.sin(half)));
    g.writeNumberField("w", round(Math.cos(half)));
    g.writeEndObject();
  }

  static void pose(JsonGenerator g, String field, ArPose p) throws IOException {
    g.writeObjectFieldStart(field);
    vector(g, "position", p.x(), p.y());
    quaternion(g, "orientation", p.th());
    g.writeEndObject();
  }

  static void color(JsonGenerator g, String field, int rgb, double alpha) throws IOException {
    g.writeObjectFieldStart(field);
    g.writeNumberField("r", round(((rgb >> 16) & 0xFF) / 255.0));
    g.writeNumberField("g", round(((rgb >> 8) & 0xFF) / 255.0));
    g.writeNumberField("b", round((rgb & 0xFF) / 255.0));
    g.writeNumberField("a", alpha);
    g.writeEndObject();
  }

  /** Six decimals: enough for a unit quaternion or a colour channel. */
  static double round(double v) {
    return Math.round(v * 1e6) / 1e6;
  }

  /** The heading of a quaternion about z, degrees. */
  static double headingDeg(double qz, double qw) {
    return Math.toDegrees(2 * Math.atan2(qz, qw));
  }
}
