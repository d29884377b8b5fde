package org.jaria.mapping;

/**
 * A log no map can be built from, with a message that says why and what to do, e.g. "the robot
 * never moved while logging: drive it around with the laser on".
 */
public final class MapBuildException extends Exception {

  private static final long serialVersionUID = 1L;

  /** A log that cannot become a map, for the reason given. */
  public MapBuildException(String message) {
    super(message);
  }
}
