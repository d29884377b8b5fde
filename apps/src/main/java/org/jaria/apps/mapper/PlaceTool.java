package org.jaria.apps.mapper;

import java.util.HashSet;
import java.util.Locale;
import java.util.Set;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseEvent;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMapObject;

/**
 * Places a goal, a goal with heading, the home or a dock. Click to place; for objects with a
 * heading, press where it goes and drag towards where it should face. Goals and docks get a fresh
 * name ("Goal 4"), which a double-click with the Select tool changes.
 */
public final class PlaceTool implements MapTool {

  private final ObjectKind kind;
  private double[] at;
  private double heading;

  /** A tool placing objects of {@code kind} (not lines or areas). */
  public PlaceTool(ObjectKind kind) {
    if (kind == ObjectKind.FORBIDDEN_AREA || kind == ObjectKind.FORBIDDEN_LINE) {
      throw new IllegalArgumentException(kind.label() + " is drawn with its own tool");
    }
    this.kind = kind;
  }

  /** The kind of object placed. */
  public ObjectKind kind() {
    return kind;
  }

  @Override
  public String name() {
    String l = kind.label();
    return Character.toUpperCase(l.charAt(0)) + l.substring(1);
  }

  @Override
  public void pressed(ToolContext c, MouseEvent e) {
    at = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    heading = 0;
    c.redraw();
  }

  @Override
  public void dragged(ToolContext c, MouseEvent e) {
    if (at == null || !kind.hasHeading()) {
      return;
    }
    double x = c.viewport().toWorldX(e.getX());
    double y = c.viewport().toWorldY(e.getY());
    if (Math.hypot(x - at[0], y - at[1]) * c.viewport().scale() > 4) {
      double step = e.isShiftDown() ? 15 : 1;
      double a = Math.toDegrees(Math.atan2(y - at[1], x - at[0]));
      heading = ArMath.fixAngle(Math.round(a / step) * step);
      c.status(String.format(Locale.ROOT, "%s heading %.0f°", name(), heading));
    }
    c.redraw();
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {
    if (at == null) {
      return;
    }
    ArMapObject o = make(c.document().content(), at[0], at[1], heading);
    at = null;
    c.document().execute(MapEdits.addObject(o));
    c.redraw();
  }

  private ArMapObject make(MapContent content, double x, double y, double th) {
    return switch (kind) {
      case GOAL -> ArMapObject.goal(freshName(content, "Goal"), x, y);
      case GOAL_WITH_HEADING -> ArMapObject.goalWithHeading(freshName(content, "Goal"), x, y, th);
      case HOME -> ArMapObject.robotHome("", x, y, th);
      case DOCK -> ArMapObject.dock(freshName(content, "Dock"), x, y, th);
      case FORBIDDEN_LINE, FORBIDDEN_AREA -> throw new IllegalStateException(kind.label());
    };
  }

  /** "Goal N" for the smallest N no object is called yet. */
  static String freshName(MapContent content, String base) {
    Set<String> used = new HashSet<>();
    for (MapObjectEntry e : content.objects()) {
      used.add(e.object().name().toLowerCase(Locale.ROOT));
    }
    for (int n = 1; ; n++) {
      String name = base + " " + n;
      if (!used.contains(name.toLowerCase(Locale.ROOT))) {
        return name;
      }
    }
  }

  @Override
  public void drawOverlay(ToolContext c, GraphicsContext gc, MapRenderer r) {
    if (at != null) {
      r.drawObject(
          gc,
          c.viewport(),
          new ArMapObject(kind.type(), new ArPose(at[0], at[1], heading), "", ""),
          true,
          false,
          0,
          0);
    }
  }

  @Override
  public void cancel() {
    at = null;
  }
}
