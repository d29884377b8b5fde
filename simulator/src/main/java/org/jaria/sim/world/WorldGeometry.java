package org.jaria.sim.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Everything solid in a simulated world: the static obstacles (map lines and points, injected
 * obstacles) in a {@link SegmentIndex}, plus the moving robots' footprints. Rays and collision
 * queries see both; a robot never sees or bumps into itself.
 *
 * <p>Used by the world thread only (not thread-safe).
 */
public final class WorldGeometry {

  /** Below this many robots, testing them all is cheaper than the grid. */
  private static final int GRID_FROM = 9;

  private SegmentIndex statics = SegmentIndex.builder().build();
  private final List<Footprint> robots = new ArrayList<>();
  private boolean[] solid = new boolean[8];
  private final RobotGrid grid = new RobotGrid();
  private boolean gridValid;
  private final RayVisitor rayVisitor = new RayVisitor();
  private final BoxVisitor boxVisitor = new BoxVisitor();

  /** Replaces the static obstacles. */
  public void setStatics(SegmentIndex index) {
    statics = index;
  }

  /** The static obstacles. */
  public SegmentIndex statics() {
    return statics;
  }

  /** Registers a robot's footprint (kept up to date by the caller); returns its index. */
  public int addRobot(Footprint f) {
    robots.add(f);
    if (robots.size() > solid.length) {
      solid = Arrays.copyOf(solid, solid.length * 2);
    }
    solid[robots.size() - 1] = true;
    gridValid = false;
    return robots.size() - 1;
  }

  /**
   * Re-indexes the robots where they stand; queries stay exact while no robot moves farther than
   * {@code margin} mm from here (call before every tick with the tick's largest possible motion,
   * and after moving robots by hand).
   */
  public void indexRobots(double margin) {
    if (robots.size() >= GRID_FROM) {
      grid.rebuild(robots, margin);
      gridValid = true;
    }
  }

  /**
   * Forgets the robot index (a robot was moved by hand); queries test every robot until the next
   * {@link #indexRobots}.
   */
  public void robotsMoved() {
    gridValid = false;
  }

  /** Makes a robot invisible to rays and collisions of others (or solid again). */
  public void setSolid(int robot, boolean isSolid) {
    solid[robot] = isSolid;
  }

  /** Number of robots registered. */
  public int robotCount() {
    return robots.size();
  }

  /**
   * Casts a ray and stores the nearest hit (map, obstacle or another robot) in {@code out}, which
   * is reset first.
   *
   * @param ignoreRobot the robot the ray starts from (-1 for none)
   */
  public void cast(
      double ox, double oy, double dx, double dy, double maxRange, int ignoreRobot, RayHit out) {
    out.reset();
    statics.cast(ox, oy, dx, dy, maxRange, out);
    if (gridValid && robots.size() >= GRID_FROM) {
      rayVisitor.set(ox, oy, dx, dy, ignoreRobot, out);
      grid.visitRay(ox, oy, dx, dy, out, maxRange, rayVisitor);
    } else {
      for (int i = 0, n = robots.size(); i < n; i++) {
        if (i != ignoreRobot && solid[i]) {
          robots.get(i).cast(ox, oy, dx, dy, out, i);
        }
      }
    }
    if (out.distance > maxRange) {
      out.reset();
    }
  }

  /**
   * Whether {@code candidate} (a footprint placed where robot {@code self} wants to go) overlaps
   * anything; the touching point nearest the footprint's centre goes to {@code out} (reset first).
   */
  public boolean collides(Footprint candidate, int self, Contact out) {
    out.reset();
    boolean any =
        statics.findContacts(
            candidate.x, candidate.y, 4, candidate.centerX(), candidate.centerY(), out);
    if (gridValid && robots.size() >= GRID_FROM) {
      double r = candidate.boundingRadius();
      boxVisitor.set(candidate, self, out);
      grid.visitBox(
          candidate.centerX() - r,
          candidate.centerY() - r,
          candidate.centerX() + r,
          candidate.centerY() + r,
          boxVisitor);
      return any || boxVisitor.any;
    }
    for (int i = 0, n = robots.size(); i < n; i++) {
      if (touchRobot(candidate, self, i, out)) {
        any = true;
      }
    }
    return any;
  }

  private boolean touchRobot(Footprint candidate, int self, int i, Contact out) {
    if (i == self || !solid[i]) {
      return false;
    }
    Footprint other = robots.get(i);
    if (candidate.overlaps(other)) {
      other.offerContact(candidate, out, i);
      return true;
    }
    return false;
  }

  /** Tests a ray against the robots the grid hands it (reused: no allocation per ray). */
  private final class RayVisitor implements RobotGrid.Visitor {
    private double ox;
    private double oy;
    private double dx;
    private double dy;
    private int ignore;
    private RayHit out;

    void set(double ox, double oy, double dx, double dy, int ignore, RayHit out) {
      this.ox = ox;
      this.oy = oy;
      this.dx = dx;
      this.dy = dy;
      this.ignore = ignore;
      this.out = out;
    }

    @Override
    public boolean visit(int robot) {
      if (robot != ignore && solid[robot]) {
        robots.get(robot).cast(ox, oy, dx, dy, out, robot);
      }
      return true;
    }
  }

  /** Tests a footprint against the robots the grid hands it (reused). */
  private final class BoxVisitor implements RobotGrid.Visitor {
    private Footprint candidate;
    private int self;
    private Contact out;
    boolean any;

    void set(Footprint candidate, int self, Contact out) {
      this.candidate = candidate;
      this.self = self;
      this.out = out;
      this.any = false;
    }

    @Override
    public boolean visit(int robot) {
      if (touchRobot(candidate, self, robot, out)) {
        any = true;
      }
      return true;
    }
  }
}
