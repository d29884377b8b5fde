package org.jaria.net.data;

import java.util.Objects;

/**
 * A drawing as a server lists it: its name (also the name of the data that gives its points) and
 * how to draw it.
 *
 * @param name the drawing's name, e.g. {@code "sonarCurrent"}
 * @param data how to draw it
 */
public record NamedDrawing(String name, ArDrawingData data) {

  /** Checks that both are there. */
  public NamedDrawing {
    Objects.requireNonNull(name, "name");
    Objects.requireNonNull(data, "data");
  }
}
