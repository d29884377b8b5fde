package org.jaria.apps.mapper;

import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.LongSupplier;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapFormatException;

/**
 * The map file behind a document: the {@link ArMap} as read (which keeps every line the editor does
 * not understand) and which of its objects carry which editor numbers. Saving brings the {@link
 * ArMap} up to date with the edited content by touching only what changed — removed objects are
 * removed, changed ones replaced in place, new ones appended, lines and points rewritten only if
 * they changed — so an unedited map is written back byte for byte.
 *
 * <p>Thread-safe: saving runs on a worker thread while the editor goes on.
 */
public final class MapFile {

  private final ArMap map;
  private final Map<Long, ArMapObject> objectsById = new LinkedHashMap<>();

  private MapFile(ArMap map) {
    this.map = map;
  }

  /**
   * Reads a map file and numbers its lines and objects, giving the content the editor starts with.
   *
   * @throws MapFormatException if the file is not a map (message names file and line)
   * @throws IOException if it cannot be read
   */
  public static Loaded read(Path file, LongSupplier ids) throws MapFormatException, IOException {
    return wrap(ArMap.readFile(file), ids);
  }

  /** Numbers an already loaded (or new, empty) map's lines and objects. */
  public static Loaded wrap(ArMap map, LongSupplier ids) {
    MapFile f = new MapFile(map);
    List<MapLine> lines = new ArrayList<>();
    for (ArLineSegment s : map.getLines()) {
      lines.add(new MapLine(ids.getAsLong(), s));
    }
    List<MapObjectEntry> objects = new ArrayList<>();
    for (ArMapObject o : map.getMapObjects()) {
      long id = ids.getAsLong();
      objects.add(new MapObjectEntry(id, o));
      f.objectsById.put(id, o);
    }
    return new Loaded(f, new MapContent(lines, map.getPoints(), objects));
  }

  /**
   * A map file and the content read from it.
   *
   * @param file the file state
   * @param content what the editor starts with
   */
  public record Loaded(MapFile file, MapContent content) {}

  /** The map type of the file ("2D-Map", ...). */
  public synchronized String mapType() {
    return map.getMapType();
  }

  /** The header's resolution in mm, or -1. */
  public synchronized int resolution() {
    return map.getResolution();
  }

  /**
   * Brings the map up to date with {@code content} and writes it to {@code file} (through a
   * temporary file in the same folder, so a failed save never leaves half a map).
   *
   * @throws IOException if writing fails; the file on disk is then unchanged
   */
  public synchronized void save(MapContent content, Path file) throws IOException {
    update(content);
    Path abs = file.toAbsolutePath();
    Path dir = abs.getParent();
    // Written with the default permissions (not a temp file's private ones), then moved.
    Path tmp = dir.resolve("." + abs.getFileName() + ".saving");
    try {
      map.writeFile(tmp);
      keepPermissions(abs, tmp);
      try {
        Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
      } catch (AtomicMoveNotSupportedException e) {
        Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
      }
    } finally {
      Files.deleteIfExists(tmp);
    }
  }

  private static void keepPermissions(Path original, Path replacement) {
    try {
      if (Files.exists(original)) {
        Files.setPosixFilePermissions(replacement, Files.getPosixFilePermissions(original));
      }
    } catch (IOException | UnsupportedOperationException e) {
      // Not a POSIX file system, or not ours to change: the default permissions will do.
    }
  }

  /** The map as it would be written for {@code content} (brought up to date first). */
  public synchronized ArMap toArMap(MapContent content) {
    update(content);
    return map;
  }

  private void update(MapContent content) {
    Map<Long, ArMapObject> now = new LinkedHashMap<>();
    for (MapObjectEntry e : content.objects()) {
      now.put(e.id(), e.object());
    }
    for (Map.Entry<Long, ArMapObject> was : objectsById.entrySet()) {
      ArMapObject current = now.get(was.getKey());
      if (current == null) {
        map.removeMapObject(was.getValue());
      } else if (!current.equals(was.getValue())) {
        map.replaceMapObject(was.getValue(), current);
      }
    }
    for (Map.Entry<Long, ArMapObject> e : now.entrySet()) {
      if (!objectsById.containsKey(e.getKey())) {
        map.addMapObject(e.getValue());
      }
    }
    objectsById.clear();
    objectsById.putAll(now);
    List<ArLineSegment> segments = content.segments();
    if (!segments.equals(map.getLines())) {
      map.setLines(segments);
    }
    if (!content.points().equals(map.getPoints())) {
      map.setPoints(content.points());
    }
  }
}
