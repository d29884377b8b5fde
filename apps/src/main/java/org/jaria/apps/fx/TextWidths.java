package org.jaria.apps.fx;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import javafx.scene.text.Font;
import javafx.scene.text.Text;

/** Widths of texts in one font, measured once each: measuring text is slow next to drawing it. */
public final class TextWidths {

  private final Font font;
  private final Map<String, Double> widths = new ConcurrentHashMap<>();

  /** Widths in {@code font}. */
  public TextWidths(Font font) {
    this.font = font;
  }

  /** The width of {@code text} in pixels, with a pixel of room on each side. */
  public double of(String text) {
    return widths.computeIfAbsent(
        text,
        t -> {
          Text measure = new Text(t);
          measure.setFont(font);
          return Math.ceil(measure.getLayoutBounds().getWidth()) + 2;
        });
  }
}
