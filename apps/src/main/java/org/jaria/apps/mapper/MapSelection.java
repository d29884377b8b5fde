package org.jaria.apps.mapper;

import java.util.BitSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * What is selected in the map editor: lines and objects by their editor numbers, sensor points by
 * their index. Used on the JavaFX thread.
 */
public final class MapSelection {

  private final Set<Long> ids = new LinkedHashSet<>();
  private BitSet points = new BitSet();
  private final List<Runnable> listeners = new CopyOnWriteArrayList<>();

  /** Calls {@code r} after every change. */
  public void addListener(Runnable r) {
    listeners.add(r);
  }

  private void changed() {
    for (Runnable r : listeners) {
      r.run();
    }
  }

  /** The selected lines and objects (a copy). */
  public Set<Long> ids() {
    return Set.copyOf(ids);
  }

  /** The selected points (a copy). */
  public BitSet points() {
    return (BitSet) points.clone();
  }

  /** Whether item {@code id} is selected. */
  public boolean contains(long id) {
    return ids.contains(id);
  }

  /** Whether point {@code i} is selected. */
  public boolean containsPoint(int i) {
    return points.get(i);
  }

  /** Whether nothing is selected. */
  public boolean isEmpty() {
    return ids.isEmpty() && points.isEmpty();
  }

  /** The number of selected items and points. */
  public int size() {
    return ids.size() + points.cardinality();
  }

  /** The only selected item, or -1 if not exactly one item (and no point) is selected. */
  public long single() {
    return ids.size() == 1 && points.isEmpty() ? ids.iterator().next() : -1;
  }

  /** Selects exactly these items and points. */
  public void set(Set<Long> newIds, BitSet newPoints) {
    ids.clear();
    ids.addAll(newIds);
    points = (BitSet) newPoints.clone();
    changed();
  }

  /** Adds items and points to the selection. */
  public void add(Set<Long> moreIds, BitSet morePoints) {
    ids.addAll(moreIds);
    points.or(morePoints);
    changed();
  }

  /** Adds or removes one item (shift-click). */
  public void toggle(long id) {
    if (!ids.remove(id)) {
      ids.add(id);
    }
    changed();
  }

  /** Selects nothing. */
  public void clear() {
    if (!isEmpty()) {
      ids.clear();
      points.clear();
      changed();
    }
  }

  /**
   * Drops what no longer exists in {@code content} (after undo, redo or delete); point indices do
   * not survive a change of the points, so the point selection is dropped when they changed.
   */
  public void retainExisting(MapContent content, boolean pointsChanged) {
    boolean changed = ids.removeIf(id -> !content.contains(id));
    if (pointsChanged && !points.isEmpty()) {
      points.clear();
      changed = true;
    }
    if (changed) {
      changed();
    }
  }
}
