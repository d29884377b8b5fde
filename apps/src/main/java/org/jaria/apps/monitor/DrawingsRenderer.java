package org.jaria.apps.monitor;

import java.util.Comparator;
import java.util.List;
import java.util.Map;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import org.jaria.apps.fx.Viewport;
import org.jaria.net.data.ArDrawingData;
import org.jaria.net.data.NamedDrawing;
import org.jaria.net.data.Points;

/**
 * Draws a server's drawings (ArServerInfoDrawings) as MobileEyes does, lowest layer first: {@code
 * polyDots} as filled circles {@code size} mm across, {@code polyArrows} as arrows {@code size} mm
 * long pointing at the robot, {@code polyLine} as a line {@code size} pixels wide, {@code
 * polyPoints} as single pixels, {@code polySegments} as segments from each even point to the next.
 * Drawings hidden by default ({@code DefaultOff}, {@code AlwaysOff}) and unknown shapes are left
 * out.
 */
final class DrawingsRenderer {

  private DrawingsRenderer() {}

  static void draw(
      GraphicsContext gc,
      Viewport vp,
      List<NamedDrawing> drawings,
      Map<String, Points> points,
      double robotX,
      double robotY) {
    List<NamedDrawing> ordered =
        drawings.stream().sorted(Comparator.comparingInt(d -> d.data().layer())).toList();
    for (NamedDrawing d : ordered) {
      Points p = points.get(d.name());
      String vis = d.data().visibility();
      if (p == null || vis.endsWith("Off")) {
        continue;
      }
      draw(gc, vp, d.data(), p, robotX, robotY);
    }
  }

  private static void draw(
      GraphicsContext gc, Viewport vp, ArDrawingData d, Points p, double rx, double ry) {
    int rgb = d.primaryColor();
    Color c = Color.rgb((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF);
    gc.setFill(c);
    gc.setStroke(c);
    switch (d.shape()) {
      case "polyDots" -> {
        double r = Math.max(1.5, d.size() * vp.scale() / 2);
        for (int i = 0; i < p.size(); i++) {
          gc.fillOval(vp.toScreenX(p.x(i)) - r, vp.toScreenY(p.y(i)) - r, 2 * r, 2 * r);
        }
      }
      case "polyPoints" -> {
        for (int i = 0; i < p.size(); i++) {
          gc.fillRect(vp.toScreenX(p.x(i)), vp.toScreenY(p.y(i)), 1, 1);
        }
      }
      case "polyLine" -> {
        gc.setLineWidth(Math.max(1, d.size()));
        for (int i = 1; i < p.size(); i++) {
          line(gc, vp, p.x(i - 1), p.y(i - 1), p.x(i), p.y(i));
        }
      }
      case "polySegments" -> {
        gc.setLineWidth(Math.max(1, d.size()));
        for (int i = 0; i + 1 < p.size(); i += 2) {
          line(gc, vp, p.x(i), p.y(i), p.x(i + 1), p.y(i + 1));
        }
      }
      case "polyArrows" -> {
        gc.setLineWidth(1.5);
        for (int i = 0; i < p.size(); i++) {
          // An arrow size mm long from outside, ending at the point, pointing at the robot.
          double dx = rx - p.x(i);
          double dy = ry - p.y(i);
          double len = Math.hypot(dx, dy);
          if (len < 1) {
            continue;
          }
          double sx = p.x(i) - dx / len * d.size();
          double sy = p.y(i) - dy / len * d.size();
          line(gc, vp, sx, sy, p.x(i), p.y(i));
        }
      }
      default -> {
        // A shape MobileEyes may know and JAria does not: not drawn.
      }
    }
  }

  private static void line(
      GraphicsContext gc, Viewport vp, double x1, double y1, double x2, double y2) {
    gc.strokeLine(vp.toScreenX(x1), vp.toScreenY(y1), vp.toScreenX(x2), vp.toScreenY(y2));
  }
}
