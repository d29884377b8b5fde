package org.jaria.sim;

import java.util.List;
import org.jaria.geom.ArLineSegment;

/**
 * An obstacle injected into a world with {@link SimWorld#injectObstacle} or {@link
 * SimWorld#injectBox}: walls that robots bump into and sensors see, until removed with {@link
 * SimWorld#removeObstacle}.
 *
 * @param id the world's number for it
 * @param segments its walls, mm
 */
public record SimObstacle(int id, List<ArLineSegment> segments) {

  /** Copies the list. */
  public SimObstacle {
    segments = List.copyOf(segments);
  }
}
