package org.jaria.apps.fx;

import java.util.ArrayList;
import java.util.List;

/**
 * Places the names of goals, docks and the like (the map editor's and the monitor's) so that no two
 * overlap, none covers a marker (its own, another labelled object's, or one without a name such as
 * the home), and none reaches past the edge of the picture: each label tries the right of its
 * marker, then the left, above and below, and is left out when none of those is free (zoom in to
 * see it). A side where the name crosses no wall is preferred (a name across the map's outer wall
 * looks cut off); when every free side crosses one, the first free side is used. Labels are placed
 * in the order given, so the caller lists the ones that must show (the selection) first.
 *
 * <p>Screen coordinates, pixels; a plain function over values.
 */
public final class LabelPlacer {

  /** Half the size of an object's marker, and the gap between marker and label. */
  public static final double MARKER = 7;

  private static final double GAP = 10;

  /**
   * A label to place.
   *
   * @param x the marker's centre
   * @param y the marker's centre
   * @param width the text's width
   * @param height the text's height
   * @param text the text
   * @param tag what the label names, for the caller (null if it does not need it)
   */
  public record Label(double x, double y, double width, double height, String text, Object tag) {
    /** A label without a tag. */
    public Label(double x, double y, double width, double height, String text) {
      this(x, y, width, height, text, null);
    }
  }

  /**
   * Where a label goes.
   *
   * @param label the label
   * @param left the text's left edge
   * @param centerY the text's vertical centre
   */
  public record Placed(Label label, double left, double centerY) {
    /** The text's top edge. */
    public double top() {
      return centerY - label.height() / 2;
    }

    /** The text's right edge. */
    public double right() {
      return left + label.width();
    }

    /** The text's bottom edge. */
    public double bottom() {
      return centerY + label.height() / 2;
    }
  }

  private LabelPlacer() {}

  /** The labels that fit, with nothing else on the picture and no edge to keep inside. */
  public static List<Placed> place(List<Label> labels) {
    return place(
        labels, new double[0], new double[0], Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);
  }

  /**
   * The labels that fit, each where it overlaps nothing placed before it.
   *
   * @param otherMarkers centres of markers without a label, as x, y pairs: no label covers them
   * @param walls wall segments as x1, y1, x2, y2 quadruples: a side crossing none is preferred
   * @param width the picture's width: a label lies wholly within 0..width
   * @param height the picture's height: a label lies wholly within 0..height
   */
  public static List<Placed> place(
      List<Label> labels, double[] otherMarkers, double[] walls, double width, double height) {
    List<double[]> taken = new ArrayList<>();
    for (Label l : labels) {
      taken.add(marker(l.x(), l.y()));
    }
    for (int i = 0; i + 1 < otherMarkers.length; i += 2) {
      taken.add(marker(otherMarkers[i], otherMarkers[i + 1]));
    }
    List<Placed> out = new ArrayList<>();
    for (Label l : labels) {
      Placed chosen = null;
      for (Placed p : candidates(l, width, height)) {
        double[] r = {p.left(), p.top(), p.right(), p.bottom()};
        boolean inside = r[0] >= 0 && r[1] >= 0 && r[2] <= width && r[3] <= height;
        if (!inside || taken.stream().anyMatch(t -> overlaps(t, r))) {
          continue;
        }
        if (!crossesAny(walls, r)) {
          chosen = p;
          break;
        }
        if (chosen == null) {
          chosen = p; // free, but across a wall: only if no side is clear
        }
      }
      if (chosen != null) {
        taken.add(new double[] {chosen.left(), chosen.top(), chosen.right(), chosen.bottom()});
        out.add(chosen);
      }
    }
    return out;
  }

  private static boolean crossesAny(double[] walls, double[] r) {
    for (int i = 0; i + 3 < walls.length; i += 4) {
      if (crosses(walls[i], walls[i + 1], walls[i + 2], walls[i + 3], r)) {
        return true;
      }
    }
    return false;
  }

  /** Whether the segment (x1, y1)-(x2, y2) passes through the rectangle {x0, y0, x1, y1}. */
  static boolean crosses(double x1, double y1, double x2, double y2, double[] r) {
    // Liang-Barsky: clip the segment's parameter range to each of the four sides in turn.
    double dx = x2 - x1;
    double dy = y2 - y1;
    double[] p = {-dx, dx, -dy, dy};
    double[] q = {x1 - r[0], r[2] - x1, y1 - r[1], r[3] - y1};
    double t0 = 0;
    double t1 = 1;
    for (int i = 0; i < 4; i++) {
      if (p[i] == 0) {
        if (q[i] < 0) {
          return false; // parallel to this side and outside it
        }
      } else {
        double t = q[i] / p[i];
        if (p[i] < 0) {
          t0 = Math.max(t0, t);
        } else {
          t1 = Math.min(t1, t);
        }
        if (t0 > t1) {
          return false;
        }
      }
    }
    return true;
  }

  private static double[] marker(double x, double y) {
    return new double[] {x - MARKER, y - MARKER, x + MARKER, y + MARKER};
  }

  /**
   * Right of the marker, left, above, below; each slid along the side it is on to stay inside the
   * picture (a marker by the top edge keeps its name beside it, a little lower).
   */
  private static List<Placed> candidates(Label l, double width, double height) {
    double h = l.height();
    double w = l.width();
    double y = clamp(l.y(), h / 2, height - h / 2);
    double x = clamp(l.x() - w / 2, 0, width - w);
    return List.of(
        new Placed(l, l.x() + GAP, y),
        new Placed(l, l.x() - GAP - w, y),
        new Placed(l, x, l.y() - MARKER - h / 2 - 2),
        new Placed(l, x, l.y() + MARKER + h / 2 + 2));
  }

  /** {@code v} within min..max; as it is when the picture has no edge or the label is too big. */
  private static double clamp(double v, double min, double max) {
    return max < min || Double.isInfinite(max) ? v : Math.max(min, Math.min(max, v));
  }

  /** Whether two rectangles {x0, y0, x1, y1} share any area. */
  public static boolean overlaps(double[] a, double[] b) {
    return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
  }
}
