package org.jaria.sim;

import java.util.Locale;
import org.jaria.sim.world.MapCost;

/**
 * The most a map may cost the simulator, counted by what it holds (see {@link MapCost}), never by
 * its file's size: a 60 MB file of short walls is fine, a few thousand walls kilometres long are
 * not. A map over budget is refused before anything is built for it, with a message that says which
 * count is too high; {@code jaria sim -m}, a client's map load and {@code jaria map info} apply the
 * same {@link #DEFAULT}.
 *
 * @param maxLines most wall lines
 * @param maxPoints most DATA points
 * @param maxCellEntries most entries in the simulator's spatial index (4 bytes each)
 */
public record MapBudget(long maxLines, long maxPoints, long maxCellEntries) {

  /**
   * One million lines, four million points, 32 million index entries: a few hundred megabytes at
   * most, ten times the largest laser-built building maps.
   */
  public static final MapBudget DEFAULT = new MapBudget(1_000_000, 4_000_000, 32_000_000);

  /** Checks the limits. */
  public MapBudget {
    if (maxLines < 0 || maxPoints < 0 || maxCellEntries < 0) {
      throw new IllegalArgumentException("map limits must be 0 or more");
    }
  }

  /** Why {@code cost} is over this budget, or null if it fits. */
  public String overBy(MapCost cost) {
    if (cost.lines() > maxLines) {
      return String.format(
          Locale.ROOT,
          "%,d lines (the simulator takes at most %,d): simplify the walls in the map editor",
          cost.lines(),
          maxLines);
    }
    if (cost.points() > maxPoints) {
      return String.format(
          Locale.ROOT,
          "%,d points (the simulator takes at most %,d): thin them to a coarser resolution",
          cost.points(),
          maxPoints);
    }
    if (cost.cellEntries() > maxCellEntries) {
      return String.format(
          Locale.ROOT,
          "walls that cross up to %,d grid cells (the simulator indexes at most %,d): the map"
              + " spans too far for its lines; split long lines or remove stray far-away ones",
          cost.cellEntries(),
          maxCellEntries);
    }
    return null;
  }

  /**
   * Throws if {@code cost} is over this budget.
   *
   * @throws MapTooBigException saying which count is over and what to do
   */
  public void check(MapCost cost, String source) {
    String why = overBy(cost);
    if (why != null) {
      throw new MapTooBigException("map " + source + " is too big for the simulator: " + why);
    }
  }

  /** A map that costs more than the simulator's budget. */
  public static final class MapTooBigException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    MapTooBigException(String message) {
      super(message);
    }
  }
}
