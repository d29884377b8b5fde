package org.jaria.map;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;

/**
 * A named object on a map, one {@code Cairn:} line: a goal, the robot's home, a dock, a forbidden
 * line or area, or a custom type declared by a {@code MapInfo:} line. ARIA's {@code ArMapObject},
 * immutable.
 *
 * <p>File form: {@code Cairn: <type> <x> <y> <th> "<description>" <icon> "<name>" [x1 y1 x2 y2]}
 * (x, y, th are real numbers; the label a user sees is the name).
 *
 * <p><b>Rotated areas.</b> Objects with a from/to pair describe either a line (ForbiddenLine: the
 * segment from (x1,y1) to (x2,y2), never rotated) or a rectangle (ForbiddenArea and other area
 * types). Like ARIA's ArMapObject (and Mapper3, which writes these files), the rectangle is the
 * axis-aligned box with corners (x1,y1) and (x2,y2) <em>rotated by th about the map origin</em>;
 * the pose's x and y do not move it. Real files mostly hold unrotated areas written as {@code 0 0
 * 0.000000} plus absolute corners, where the distinction does not arise. Use {@link
 * #forbiddenArea(double, double, double, double, double)} to build a rotated area from its centre
 * without doing that arithmetic yourself.
 *
 * @param type the type ("Goal", "GoalWithHeading", "RobotHome", "Dock", "ForbiddenLine",
 *     "ForbiddenArea", or a custom one); one word
 * @param pose position (mm) and heading (degrees)
 * @param description free text; never contains a double quote or line break
 * @param iconName one word, usually "ICON"
 * @param name the label (may be ""); never contains a double quote or line break
 * @param hasFromTo whether the object has a from/to pair (lines and areas)
 * @param fromPose the first corner or end point (heading 0), null if {@code !hasFromTo}
 * @param toPose the opposite corner or other end point, null if {@code !hasFromTo}
 */
public record ArMapObject(
    String type,
    ArPose pose,
    String description,
    String iconName,
    String name,
    boolean hasFromTo,
    ArPose fromPose,
    ArPose toPose) {

  /** Checks that the object can be written to a map file and read back unchanged. */
  public ArMapObject {
    if (type == null || type.isEmpty() || hasBlankOrQuote(type)) {
      throw new IllegalArgumentException(
          "map object type must be one word without quotes, not '" + type + "'");
    }
    if (pose == null) {
      throw new IllegalArgumentException("map object " + type + " needs a pose");
    }
    description = description == null ? "" : description;
    name = name == null ? "" : name;
    iconName = iconName == null || iconName.isEmpty() ? "ICON" : iconName;
    checkText(description, "description");
    checkText(name, "name");
    if (hasBlankOrQuote(iconName)) {
      throw new IllegalArgumentException("icon name must be one word, not '" + iconName + "'");
    }
    if (hasFromTo && (fromPose == null || toPose == null)) {
      throw new IllegalArgumentException(type + " has from/to but a corner is missing");
    }
    if (!hasFromTo) {
      fromPose = null;
      toPose = null;
    }
    pose = clean(pose);
    if (hasFromTo) {
      fromPose = clean(fromPose);
      toPose = clean(toPose);
    }
  }

  /** A point object without from/to: a goal, home, dock... */
  public ArMapObject(String type, ArPose pose, String description, String name) {
    this(type, pose, description, "ICON", name, false, null, null);
  }

  private static boolean hasBlankOrQuote(String s) {
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if (Character.isWhitespace(c) || c == '"' || c < 0x20) {
        return true;
      }
    }
    return false;
  }

  private static void checkText(String s, String what) {
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if (c == '"' || c == '\n' || c == '\r') {
        throw new IllegalArgumentException(
            "map object " + what + " cannot contain quotes or line breaks: '" + s + "'");
      }
    }
  }

  /** Checks finiteness and turns -0.0 into 0.0, which a file cannot tell apart. */
  private static ArPose clean(ArPose p) {
    if (!Double.isFinite(p.x()) || !Double.isFinite(p.y()) || !Double.isFinite(p.th())) {
      throw new IllegalArgumentException("map object coordinates must be finite: " + p);
    }
    return new ArPose(p.x() + 0.0, p.y() + 0.0, p.th() + 0.0);
  }

  /** A goal (no particular heading) called {@code name}. */
  public static ArMapObject goal(String name, double x, double y) {
    return new ArMapObject("Goal", new ArPose(x, y, 0), "", name);
  }

  /** A goal the robot should reach facing {@code th} degrees. */
  public static ArMapObject goalWithHeading(String name, double x, double y, double th) {
    return new ArMapObject("GoalWithHeading", new ArPose(x, y, th), "", name);
  }

  /** The robot's home (where localization starts). */
  public static ArMapObject robotHome(String name, double x, double y, double th) {
    return new ArMapObject("RobotHome", new ArPose(x, y, th), "", name);
  }

  /** A docking (charging) station the robot approaches facing {@code th}. */
  public static ArMapObject dock(String name, double x, double y, double th) {
    return new ArMapObject("Dock", new ArPose(x, y, th), "", name);
  }

  /** A line the robot must not cross, from (x1,y1) to (x2,y2). */
  public static ArMapObject forbiddenLine(double x1, double y1, double x2, double y2) {
    return new ArMapObject(
        "ForbiddenLine",
        new ArPose(x1, y1, 0),
        "",
        "ICON",
        "",
        true,
        new ArPose(x1, y1),
        new ArPose(x2, y2));
  }

  /** An axis-aligned area the robot must not enter, written as Mapper3 does (pose 0 0 0). */
  public static ArMapObject forbiddenArea(double x1, double y1, double x2, double y2) {
    return new ArMapObject(
        "ForbiddenArea",
        ArPose.ORIGIN,
        "",
        "ICON",
        "",
        true,
        new ArPose(Math.min(x1, x2), Math.min(y1, y2)),
        new ArPose(Math.max(x1, x2), Math.max(y1, y2)));
  }

  /**
   * A forbidden rectangle of {@code width} × {@code height} mm centred at ({@code cx}, {@code cy})
   * and turned {@code th} degrees counter-clockwise. The pose holds the centre and angle; the
   * corners are stored in the frame rotated by th about the origin, as the file format requires.
   */
  public static ArMapObject forbiddenArea(
      double cx, double cy, double width, double height, double th) {
    double r = Math.toRadians(th);
    double c = Math.cos(r);
    double s = Math.sin(r);
    // The centre expressed in the rotated frame (rotate by -th).
    double ux = cx * c + cy * s;
    double uy = -cx * s + cy * c;
    return new ArMapObject(
        "ForbiddenArea",
        new ArPose(cx, cy, th),
        "",
        "ICON",
        "",
        true,
        new ArPose(ux - width / 2, uy - height / 2),
        new ArPose(ux + width / 2, uy + height / 2));
  }

  /** Whether this is a goal the robot can be sent to (Goal or GoalWithHeading). */
  public boolean isGoal() {
    return type.equals("Goal") || type.equals("GoalWithHeading");
  }

  /** Whether the from/to pair is a line (ForbiddenLine and other types ending in "Line"). */
  public boolean isLineType() {
    return hasFromTo && type.endsWith("Line");
  }

  /** Whether the from/to pair is a rectangle (ForbiddenArea and other area types). */
  public boolean isAreaType() {
    return hasFromTo && !isLineType();
  }

  /** The straight from→to segment, unrotated (ARIA's getFromToSegment); null without from/to. */
  public ArLineSegment getFromToSegment() {
    return hasFromTo ? new ArLineSegment(fromPose, toPose) : null;
  }

  /**
   * The geometry of a from/to object in map coordinates: one segment for a line type, the four
   * edges of the (rotated) rectangle for an area type, nothing for point objects.
   */
  public List<ArLineSegment> getFromToSegments() {
    if (!hasFromTo) {
      return List.of();
    }
    if (isLineType()) {
      return List.of(getFromToSegment());
    }
    double[] c = corners();
    return List.of(
        new ArLineSegment(c[0], c[1], c[2], c[3]),
        new ArLineSegment(c[2], c[3], c[4], c[5]),
        new ArLineSegment(c[4], c[5], c[6], c[7]),
        new ArLineSegment(c[6], c[7], c[0], c[1]));
  }

  /** Corners (x1,y1),(x2,y1),(x2,y2),(x1,y2) rotated by th about the origin, flattened. */
  private double[] corners() {
    double r = Math.toRadians(pose.th());
    double c = Math.cos(r);
    double s = Math.sin(r);
    double fx = fromPose.x();
    double fy = fromPose.y();
    double tx = toPose.x();
    double ty = toPose.y();
    return new double[] {
      fx * c - fy * s, fx * s + fy * c,
      tx * c - fy * s, tx * s + fy * c,
      tx * c - ty * s, tx * s + ty * c,
      fx * c - ty * s, fx * s + ty * c
    };
  }

  /**
   * Whether the point (x, y) (mm, map coordinates) lies inside this object's rectangle, edges
   * included. Always false for point objects and line types.
   */
  public boolean contains(double x, double y) {
    if (!isAreaType()) {
      return false;
    }
    double r = Math.toRadians(pose.th());
    double c = Math.cos(r);
    double s = Math.sin(r);
    double ux = x * c + y * s;
    double uy = -x * s + y * c;
    double eps = 1e-6;
    return ux >= Math.min(fromPose.x(), toPose.x()) - eps
        && ux <= Math.max(fromPose.x(), toPose.x()) + eps
        && uy >= Math.min(fromPose.y(), toPose.y()) - eps
        && uy <= Math.max(fromPose.y(), toPose.y()) + eps;
  }

  /** The {@code Cairn:} line for this object, as it would be written to a map file. */
  public String toMapLine() {
    return MapFormat.formatObject(this);
  }
}
