package org.jaria.apps.mapper;

import java.util.function.LongSupplier;

/**
 * One edit of a map, as the user names it in the Edit menu ("Undo Add forbidden area"). A command
 * computes the content after the edit from the content before it; the {@link MapDocument} keeps
 * both for undo and redo. See {@link MapEdits} for the editor's commands.
 */
public interface MapEdit {

  /** What the edit does, e.g. "Add goal" (shown after "Undo"/"Redo"). */
  String name();

  /**
   * The content after this edit.
   *
   * @param before the content before it
   * @param newIds gives editor numbers for items this edit creates
   * @throws IllegalArgumentException if the edit cannot apply (e.g. its item is gone)
   */
  MapContent apply(MapContent before, LongSupplier newIds);
}
