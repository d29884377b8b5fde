package org.jaria.web.model;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Everything that moves, at one instant: the clock and every robot. Together with the {@link
 * MapLayer} it is all a viewer draws.
 *
 * @param clock when
 * @param robots every robot, names unique
 */
public record WorldFrame(ClockFrame clock, List<RobotFrame> robots) {

  /** Checks and copies. */
  public WorldFrame {
    Objects.requireNonNull(clock, "clock");
    robots = List.copyOf(robots);
    for (int i = 0; i < robots.size(); i++) {
      for (int j = 0; j < i; j++) {
        if (robots.get(i).name().equals(robots.get(j).name())) {
          throw new IllegalArgumentException(
              "two robots are named " + robots.get(i).name() + "; give each a name of its own");
        }
      }
    }
  }

  /** The robot named {@code name}. */
  public Optional<RobotFrame> robot(String name) {
    return robots.stream().filter(r -> r.name().equals(name)).findFirst();
  }
}
