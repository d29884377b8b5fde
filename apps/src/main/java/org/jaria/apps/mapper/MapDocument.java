package org.jaria.apps.mapper;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.map.ArMap;

/**
 * A map being edited: its current {@link MapContent}, the undo and redo history, the file it came
 * from and whether it has unsaved changes. Edits are {@link MapEdit}s run through {@link #execute};
 * each one records the content before and after, so undo and redo are exact.
 *
 * <p>Used on the JavaFX thread; saving hands an immutable content to {@link MapFile} on a worker
 * thread.
 */
public final class MapDocument {

  /** How many edits can be undone. */
  public static final int UNDO_LIMIT = 200;

  /**
   * One edit in the history. Every state of the map is named by the number of the edit that made it
   * (0 for the state the document started in), which is how "saved" is remembered.
   */
  private record Step(long number, String name, MapContent before, MapContent after) {}

  private final AtomicLong ids;
  private final MapFile file;
  private final Deque<Step> undo = new ArrayDeque<>();
  private final Deque<Step> redo = new ArrayDeque<>();
  private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
  private MapContent content;
  private long nextStep = 1;
  // The state under the oldest undoable edit (0 until old edits are forgotten).
  private long floor;
  private long saved;
  private Path path;
  private final String untitledName;

  /**
   * A document for a loaded map.
   *
   * @param loaded the file and its numbered content (from {@link MapFile#read})
   * @param path where it was read from, or null for a new map
   * @param ids the number source that numbered the content (continues for new items)
   */
  public MapDocument(MapFile.Loaded loaded, Path path, AtomicLong ids) {
    this(loaded, path, ids, "Untitled");
  }

  /**
   * A document for a loaded map that has no file yet (a bundled map), named {@code untitledName}
   * until it is saved.
   */
  public MapDocument(MapFile.Loaded loaded, Path path, AtomicLong ids, String untitledName) {
    this.file = loaded.file();
    this.content = loaded.content();
    this.path = path;
    this.ids = ids;
    this.untitledName = untitledName;
  }

  /** A new, empty, unsaved map. */
  public static MapDocument newMap() {
    AtomicLong ids = new AtomicLong(1);
    return new MapDocument(MapFile.wrap(new ArMap(), ids::getAndIncrement), null, ids);
  }

  /** Calls {@code r} after every change of content, history or file (same thread). */
  public void addListener(Runnable r) {
    listeners.add(r);
  }

  private void changed() {
    for (Runnable r : listeners) {
      r.run();
    }
  }

  /** The current content. */
  public MapContent content() {
    return content;
  }

  /** The file state behind this document (for saving). */
  public MapFile file() {
    return file;
  }

  /** Where the map is saved, if anywhere yet. */
  public Optional<Path> path() {
    return Optional.ofNullable(path);
  }

  /** A short title: the file name, or "Untitled". */
  public String title() {
    return path == null ? untitledName : String.valueOf(path.getFileName());
  }

  /** Whether there are changes since the last save (or load). */
  public boolean isModified() {
    return saveMark() != saved;
  }

  /**
   * A name for the current state, to hand to {@link #markSaved} once it has been written (saving
   * runs in the background while editing goes on).
   */
  public long saveMark() {
    return undo.isEmpty() ? floor : undo.peek().number();
  }

  /**
   * Runs an edit and records it for undo. An edit that changes nothing is not recorded.
   *
   * @throws IllegalArgumentException if the edit cannot apply
   */
  public void execute(MapEdit command) {
    MapContent after = command.apply(content, ids::getAndIncrement);
    if (after.equals(content)) {
      return;
    }
    undo.push(new Step(nextStep++, command.name(), content, after));
    while (undo.size() > UNDO_LIMIT) {
      floor = undo.removeLast().number();
    }
    redo.clear();
    content = after;
    changed();
  }

  /** Whether there is an edit to undo. */
  public boolean canUndo() {
    return !undo.isEmpty();
  }

  /** Whether there is an undone edit to redo. */
  public boolean canRedo() {
    return !redo.isEmpty();
  }

  /** The name of the edit {@link #undo()} would revert, or "". */
  public String undoName() {
    return undo.isEmpty() ? "" : undo.peek().name();
  }

  /** The name of the edit {@link #redo()} would repeat, or "". */
  public String redoName() {
    return redo.isEmpty() ? "" : redo.peek().name();
  }

  /** Reverts the last edit; returns whether there was one. */
  public boolean undo() {
    Step s = undo.poll();
    if (s == null) {
      return false;
    }
    redo.push(s);
    content = s.before();
    changed();
    return true;
  }

  /** Repeats the last undone edit; returns whether there was one. */
  public boolean redo() {
    Step s = redo.poll();
    if (s == null) {
      return false;
    }
    undo.push(s);
    content = s.after();
    changed();
    return true;
  }

  /**
   * Records that the state named {@code mark} (see {@link #saveMark()}) is now in {@code
   * savedPath}: the document is unmodified whenever undo or redo lead back to that state.
   */
  public void markSaved(long mark, Path savedPath) {
    saved = mark;
    path = savedPath;
    changed();
  }
}
