package org.jaria.tools.mapper;

import java.util.ArrayList;
import java.util.List;

/**
 * Places the names of goals, docks and the like so that no two overlap, and none covers another
 * object's marker: each label tries the right of its marker, then the left, above and below, and is
 * left out when none of those is free (zoom in to see it). Labels are placed in the order given, so
 * the caller lists the ones that must show (the selection) first.
 *
 * <p>Screen coordinates, pixels; a plain function over values.
 */
final class LabelPlacer {

  /** Half the size of an object's marker, and the gap between marker and label. */
  static final double MARKER = 7;

  private static final double GAP = 10;

  /**
   * A label to place.
   *
   * @param x the marker's centre
   * @param y the marker's centre
   * @param width the text's width
   * @param height the text's height
   * @param text the text
   */
  record Label(double x, double y, double width, double height, String text) {}

  /**
   * Where a label goes.
   *
   * @param label the label
   * @param left the text's left edge
   * @param centerY the text's vertical centre
   */
  record Placed(Label label, double left, double centerY) {
    double top() {
      return centerY - label.height() / 2;
    }
  }

  private LabelPlacer() {}

  /** The labels that fit, each where it does not overlap anything placed before it. */
  static List<Placed> place(List<Label> labels) {
    List<double[]> taken = new ArrayList<>();
    for (Label l : labels) {
      taken.add(new double[] {l.x() - MARKER, l.y() - MARKER, l.x() + MARKER, l.y() + MARKER});
    }
    List<Placed> out = new ArrayList<>();
    for (Label l : labels) {
      for (Placed p : candidates(l)) {
        double[] r = {p.left(), p.top(), p.left() + l.width(), p.top() + l.height()};
        if (taken.stream().noneMatch(t -> overlaps(t, r))) {
          taken.add(r);
          out.add(p);
          break;
        }
      }
    }
    return out;
  }

  private static List<Placed> candidates(Label l) {
    double h = l.height();
    return List.of(
        new Placed(l, l.x() + GAP, l.y()),
        new Placed(l, l.x() - GAP - l.width(), l.y()),
        new Placed(l, l.x() - l.width() / 2, l.y() - MARKER - h / 2 - 2),
        new Placed(l, l.x() - l.width() / 2, l.y() + MARKER + h / 2 + 2));
  }

  /** Whether two rectangles {x0, y0, x1, y1} share any area. */
  static boolean overlaps(double[] a, double[] b) {
    return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
  }
}
