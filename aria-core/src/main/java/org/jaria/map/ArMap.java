package org.jaria.map;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.Charset;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;

/**
 * An ArMap {@code .map} document ({@code 2D-Map} ... {@code 2D-Map-Ex4}): wall lines, sensor
 * points, goals, home, docks, forbidden lines and areas. ARIA's {@code ArMap}; used by the
 * simulator, sonar localization, path planning and the map editor.
 *
 * <p>File layout: line 1 is the map type; then header lines {@code Key: values} ({@code MinPos},
 * {@code Resolution}, {@code MapInfo}, {@code Cairn} objects and many more); then a {@code LINES}
 * section with one {@code x1 y1 x2 y2} per row and a {@code DATA} section with one {@code x y} per
 * row, all in mm. The header's counts and bounds are not trusted: everything is computed from the
 * data.
 *
 * <p><b>Errors and tolerance.</b> Reading fails with a {@link MapFormatException} naming source and
 * line for: a first line that is not a map type; control characters in the header (a binary file);
 * a malformed {@code Cairn:} line (wrong word count, a word where a number belongs); a {@code
 * MapInfo:} line without a class or with an unclosed quote; a non-numeric {@code Resolution},
 * {@code MinPos}, {@code MaxPos}, {@code LineMinPos}, {@code LineMaxPos}, {@code NumPoints}, {@code
 * NumLines}, {@code PointsAreSorted} or {@code LinesAreSorted}; a {@code LINES} row without exactly
 * 4 numbers or a {@code DATA} row without exactly 2; text in those rows; a section keyword given
 * twice. Tolerated: blank lines anywhere, trailing blanks, CRLF line ends, tabs between numbers,
 * decimals in rows (DATA points are rounded to whole mm), unknown header lines and inactive objects
 * ({@code _Cairn:}), which are kept and written back unchanged.
 *
 * <p><b>Round trip.</b> {@link #write(Writer)} reproduces an unedited map byte for byte, provided
 * its line ends are consistent (mixed LF/CRLF files come back with the first line's ending). Edits
 * mark what they touch: changed objects are rewritten in place, and after {@link #setLines} or
 * {@link #setPoints} the section and its header bounds and counts are regenerated. Every other line
 * stays as it was.
 *
 * <p>Not thread-safe: load or build a map, then share it read-only. {@link #equals} compares
 * content (type, lines, points, objects, map info, resolution and the other header lines), so a
 * written and reloaded map equals the original.
 */
public final class ArMap {

  /** Classpath folder of the maps shipped with JAria. */
  public static final String RESOURCE_DIR = "/org/jaria/maps/";

  /** The maps shipped with JAria, for {@link #loadBundled(String)}. */
  public static final List<String> BUNDLED_MAPS = List.of("office", "hall", "columbia");

  static final Set<String> POINT_KEYS = Set.of("MinPos", "MaxPos", "NumPoints", "PointsAreSorted");
  static final Set<String> LINE_KEYS =
      Set.of("LineMinPos", "LineMaxPos", "NumLines", "LinesAreSorted");

  String sourceName;
  String mapType = "2D-Map";
  String firstLine = "2D-Map";
  boolean byteOrderMark;
  String lineSeparator = "\n";
  boolean endsWithNewline = true;
  Charset charset = StandardCharsets.UTF_8;
  final List<HeaderSlot> header = new ArrayList<>();
  final List<MapInfoEntry> mapInfo = new ArrayList<>();
  final List<BodySection> sections = new ArrayList<>();
  final List<ArLineSegment> lines = new ArrayList<>();
  ArMapPoints points = ArMapPoints.EMPTY;
  int resolution = -1;
  final List<String> warnings = new ArrayList<>();
  boolean linesEdited;
  boolean pointsEdited;

  /** The active objects, rebuilt after every object edit so reads never write. */
  private List<ArMapObject> objects = List.of();

  /** An empty map of type {@code 2D-Map}, to be filled by the edit methods. */
  public ArMap() {
    this("<new map>");
    linesEdited = true;
    pointsEdited = true;
  }

  ArMap(String sourceName) {
    this.sourceName = sourceName;
  }

  // ------------------------------------------------------------------ reading and writing

  /**
   * Reads a map file. UTF-8 text is decoded as such; anything else as ISO-8859-1, and {@link
   * #writeFile} writes with the same encoding, so names in either survive a round trip.
   *
   * @throws MapFormatException if the file is not a well-formed map (message names file and line)
   * @throws IOException if it cannot be read
   */
  public static ArMap readFile(Path file) throws MapFormatException, IOException {
    ArMap m;
    Charset cs = StandardCharsets.UTF_8;
    try {
      m = readFile(file, cs);
    } catch (CharacterCodingException notUtf8) {
      cs = StandardCharsets.ISO_8859_1;
      m = readFile(file, cs);
    }
    m.charset = cs;
    return m;
  }

  /** Streams {@code file} through a decoder that reports malformed input. */
  private static ArMap readFile(Path file, Charset cs) throws MapFormatException, IOException {
    CharsetDecoder d =
        cs.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT);
    try (Reader r = new InputStreamReader(Files.newInputStream(file), d)) {
      return MapReader.parse(r, file.toString());
    }
  }

  /**
   * Reads a map from a character stream (not closed here).
   *
   * @param sourceName a name for messages, usually the file name
   * @throws MapFormatException if the text is not a well-formed map
   * @throws IOException if reading fails
   */
  public static ArMap read(Reader in, String sourceName) throws MapFormatException, IOException {
    return MapReader.parse(in, sourceName);
  }

  /**
   * A map as a user names it on a command line: a {@code .map} file, or a bundled map's name
   * ({@link #BUNDLED_MAPS}, with or without {@code .map}; a file that exists wins). See {@link
   * MapNames}.
   *
   * @throws MapFormatException if the file is not a well-formed map
   * @throws IOException if there is no such file or bundled map, or it cannot be read: the message
   *     says which, what to do, and which maps are bundled
   */
  public static ArMap load(String fileOrBundledName) throws MapFormatException, IOException {
    String bundled = MapNames.bundledName(fileOrBundledName);
    if (bundled != null) {
      return loadBundled(bundled);
    }
    Optional<String> problem = MapNames.problem(fileOrBundledName);
    if (problem.isPresent()) {
      throw new IOException(problem.get());
    }
    return readFile(Path.of(fileOrBundledName));
  }

  /**
   * One of the maps shipped with JAria ({@link #BUNDLED_MAPS}: "office", a 30 × 20 m office floor
   * with a corridor and nine rooms; "hall", an open 20 × 15 m hall with pillars; "columbia", a real
   * building scanned by a Pioneer with a laser, 63,000 points and 470 lines).
   *
   * @throws IllegalArgumentException if there is no bundled map of that name
   */
  public static ArMap loadBundled(String name) {
    if (!BUNDLED_MAPS.contains(name)) {
      throw new IllegalArgumentException(
          "no bundled map '" + name + "'; JAria ships " + BUNDLED_MAPS);
    }
    String res = RESOURCE_DIR + name + ".map";
    try (InputStream in = ArMap.class.getResourceAsStream(res)) {
      if (in == null) {
        throw new IllegalStateException("JAria's bundled map " + res + " is missing");
      }
      return MapReader.parse(new InputStreamReader(in, StandardCharsets.UTF_8), "classpath:" + res);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read bundled map " + res, e);
    } catch (MapFormatException e) {
      throw new IllegalStateException("JAria's bundled map is broken: " + e.getMessage(), e);
    }
  }

  /** Writes the map to a file in the encoding it was read with (UTF-8 for new maps). */
  public void writeFile(Path file) throws IOException {
    try (BufferedWriter w = Files.newBufferedWriter(file, charset)) {
      write(w);
    }
  }

  /** Writes the map (see the class comment for what is kept and what is regenerated). */
  public void write(Writer out) throws IOException {
    MapWriter.write(this, out);
  }

  // ------------------------------------------------------------------ reading the content

  /** Where this map came from (file name, "classpath:...", or "&lt;new map&gt;"). */
  public String getSourceName() {
    return sourceName;
  }

  /** The map type from line 1: "2D-Map", "2D-Map-Ex", ... "2D-Map-Ex4". */
  public String getMapType() {
    return mapType;
  }

  /**
   * What was odd about the file but did not stop it loading, one "file:line: what" message each: a
   * LINES or DATA section with fewer (or more) rows than the header's NumLines or NumPoints, as
   * when a copy was cut short. Empty for a map made in memory.
   */
  public List<String> getWarnings() {
    return Collections.unmodifiableList(warnings);
  }

  /** The wall lines (LINES section), in file order; unmodifiable view. */
  public List<ArLineSegment> getLines() {
    return Collections.unmodifiableList(lines);
  }

  /** The sensor points (DATA section). */
  public ArMapPoints getPoints() {
    return points;
  }

  /** The header's {@code Resolution} (mm between points), -1 if the header has none. */
  public int getResolution() {
    return resolution;
  }

  /** The {@code MapInfo:} lines, in file order; unmodifiable. */
  public List<MapInfoEntry> getMapInfo() {
    return Collections.unmodifiableList(mapInfo);
  }

  /** Every active map object ({@code Cairn:} lines), in file order; unmodifiable. */
  public List<ArMapObject> getMapObjects() {
    return objects;
  }

  /** Rebuilds the object list from the header; called after parsing and after object edits. */
  void refreshObjects() {
    List<ArMapObject> l = new ArrayList<>();
    for (HeaderSlot s : header) {
      if (s.object != null) {
        l.add(s.object);
      }
    }
    objects = List.copyOf(l);
  }

  /** Header lines this class does not interpret (unknown keys, {@code _Cairn:}...), as read. */
  public List<String> getOtherHeaderLines() {
    List<String> l = new ArrayList<>();
    for (HeaderSlot s : header) {
      if (s.object == null
          && !s.key.equals("MapInfo")
          && !s.key.equals("Resolution")
          && !POINT_KEYS.contains(s.key)
          && !LINE_KEYS.contains(s.key)) {
        l.add(s.raw);
      }
    }
    return l;
  }

  /** The first object whose name equals {@code name}, ignoring case (ARIA's findMapObject). */
  public Optional<ArMapObject> findMapObject(String name) {
    for (ArMapObject o : getMapObjects()) {
      if (o.name().equalsIgnoreCase(name)) {
        return Optional.of(o);
      }
    }
    return Optional.empty();
  }

  /** The first object of type {@code type}, ignoring case. */
  public Optional<ArMapObject> findFirstMapObjectOfType(String type) {
    for (ArMapObject o : getMapObjects()) {
      if (o.type().equalsIgnoreCase(type)) {
        return Optional.of(o);
      }
    }
    return Optional.empty();
  }

  /** The goals (Goal and GoalWithHeading objects), in file order. */
  public List<ArMapObject> getGoals() {
    return getMapObjects().stream().filter(ArMapObject::isGoal).toList();
  }

  /** Where localization starts: the first RobotHome's pose, else the first Dock's, else empty. */
  public Optional<ArPose> findHomePose() {
    return findFirstMapObjectOfType("RobotHome")
        .or(() -> findFirstMapObjectOfType("Dock"))
        .map(ArMapObject::pose);
  }

  /**
   * Lower-left corner of the points' bounding box (computed, not the header's MinPos); the lines'
   * if there are no points; the origin for an empty map.
   */
  public ArPose getMinPos() {
    return points.isEmpty() ? getLineMinPos() : new ArPose(pointBound(0), pointBound(1));
  }

  /** Upper-right corner of the points' bounding box; see {@link #getMinPos()}. */
  public ArPose getMaxPos() {
    return points.isEmpty() ? getLineMaxPos() : new ArPose(pointBound(2), pointBound(3));
  }

  /** Lower-left corner of the lines' bounding box; the points' if there are no lines. */
  public ArPose getLineMinPos() {
    if (lines.isEmpty()) {
      return points.isEmpty() ? ArPose.ORIGIN : getMinPos();
    }
    return new ArPose(lineBound(0), lineBound(1));
  }

  /** Upper-right corner of the lines' bounding box; the points' if there are no lines. */
  public ArPose getLineMaxPos() {
    if (lines.isEmpty()) {
      return points.isEmpty() ? ArPose.ORIGIN : getMaxPos();
    }
    return new ArPose(lineBound(2), lineBound(3));
  }

  /** minX, minY, maxX, maxY of the points (which must not be empty), by index. */
  int pointBound(int which) {
    int best = which < 2 ? Integer.MAX_VALUE : Integer.MIN_VALUE;
    for (int i = 0; i < points.size(); i++) {
      int v = (which % 2 == 0) ? points.x(i) : points.y(i);
      best = which < 2 ? Math.min(best, v) : Math.max(best, v);
    }
    return best;
  }

  /** minX, minY, maxX, maxY of the lines (which must not be empty), by index. */
  double lineBound(int which) {
    double best = which < 2 ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
    for (ArLineSegment l : lines) {
      double a = which % 2 == 0 ? l.x1() : l.y1();
      double b = which % 2 == 0 ? l.x2() : l.y2();
      best = which < 2 ? Math.min(best, Math.min(a, b)) : Math.max(best, Math.max(a, b));
    }
    return best;
  }

  // ------------------------------------------------------------------ editing

  /** Replaces all wall lines; the LINES section and its header bounds are rewritten. */
  public void setLines(List<ArLineSegment> newLines) {
    List<ArLineSegment> copy = List.copyOf(newLines);
    lines.clear();
    lines.addAll(copy);
    linesEdited = true;
  }

  /** Adds one wall line; the LINES section and its header bounds are rewritten. */
  public void addLine(ArLineSegment line) {
    lines.add(Objects.requireNonNull(line, "line"));
    linesEdited = true;
  }

  /** Replaces all sensor points; the DATA section and its header bounds are rewritten. */
  public void setPoints(ArMapPoints newPoints) {
    points = Objects.requireNonNull(newPoints, "points");
    pointsEdited = true;
  }

  /** Adds an object after the last existing one (at the end of the header if there is none). */
  public void addMapObject(ArMapObject object) {
    Objects.requireNonNull(object, "object");
    int at = header.size();
    for (int i = header.size() - 1; i >= 0; i--) {
      if (header.get(i).object != null) {
        at = i + 1;
        break;
      }
    }
    header.add(at, new HeaderSlot("Cairn", null, object));
    refreshObjects();
  }

  /** Removes the first object equal to {@code object}; returns whether there was one. */
  public boolean removeMapObject(ArMapObject object) {
    for (int i = 0; i < header.size(); i++) {
      if (object.equals(header.get(i).object)) {
        header.remove(i);
        refreshObjects();
        return true;
      }
    }
    return false;
  }

  /**
   * Replaces the first object equal to {@code old} by {@code replacement}, in the same place;
   * returns whether {@code old} was found.
   */
  public boolean replaceMapObject(ArMapObject old, ArMapObject replacement) {
    Objects.requireNonNull(replacement, "replacement");
    for (HeaderSlot s : header) {
      if (old.equals(s.object)) {
        s.object = replacement;
        s.raw = null;
        refreshObjects();
        return true;
      }
    }
    return false;
  }

  // ------------------------------------------------------------------ equality

  @Override
  public boolean equals(Object o) {
    return o instanceof ArMap m
        && mapType.equals(m.mapType)
        && resolution == m.resolution
        && lines.equals(m.lines)
        && points.equals(m.points)
        && getMapObjects().equals(m.getMapObjects())
        && mapInfo.equals(m.mapInfo)
        && getOtherHeaderLines().equals(m.getOtherHeaderLines());
  }

  @Override
  public int hashCode() {
    return Objects.hash(mapType, resolution, lines, points, getMapObjects());
  }

  @Override
  public String toString() {
    return String.format(
        Locale.ROOT,
        "ArMap[%s %s, %d lines, %d points, %d objects]",
        sourceName,
        mapType,
        lines.size(),
        points.size(),
        getMapObjects().size());
  }
}
