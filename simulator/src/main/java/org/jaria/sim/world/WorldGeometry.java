package org.jaria.sim.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Everything solid in a simulated world: the static obstacles (map lines and points, injected
 * obstacles) in a {@link SegmentIndex}, plus the moving robots' footprints. Rays and collision
 * queries see both; a robot never sees or bumps into itself.
 *
 * <p>Robots are known by their number in the world, which is never given to another robot: a robot
 * can be {@link #removeRobot removed}, and rays and collisions stop seeing it at once, while hits
 * ({@link RayHit#robot}, {@link Contact#robot}) keep naming robots by number. Internally the
 * footprints stay packed in the order they were added.
 *
 * <p>Used by the world thread only (not thread-safe).
 */
public final class WorldGeometry {

  /** Below this many robots, testing them all is cheaper than the grid. */
  private static final int GRID_FROM = 9;

  private SegmentIndex statics = SegmentIndex.builder().build();
  private final List<Footprint> robots = new ArrayList<>();

  /** The number of the robot at each place of {@link #robots}. */
  private int[] numbers = new int[8];

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

  /**
   * Registers the footprint of robot {@code number} (kept up to date by the caller).
   *
   * @throws IllegalArgumentException if a robot with that number is registered
   */
  public void addRobot(int number, Footprint f) {
    if (place(number) >= 0) {
      throw new IllegalArgumentException("robot " + number + " is registered already");
    }
    int n = robots.size();
    if (n == solid.length) {
      solid = Arrays.copyOf(solid, n * 2);
      numbers = Arrays.copyOf(numbers, n * 2);
    }
    robots.add(f);
    numbers[n] = number;
    solid[n] = true;
    gridValid = false;
  }

  /**
   * Forgets robot {@code number}: from now on no ray or collision meets it. Returns whether it was
   * registered.
   */
  public boolean removeRobot(int number) {
    int i = place(number);
    if (i < 0) {
      return false;
    }
    int tail = robots.size() - i - 1;
    robots.remove(i);
    System.arraycopy(numbers, i + 1, numbers, i, tail);
    System.arraycopy(solid, i + 1, solid, i, tail);
    gridValid = false;
    return true;
  }

  /** Where robot {@code number} sits in {@link #robots}, or -1. */
  private int place(int number) {
    for (int i = 0, n = robots.size(); i < n; i++) {
      if (numbers[i] == number) {
        return i;
      }
    }
    return -1;
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

  /** Makes robot {@code number} invisible to rays and collisions of others (or solid again). */
  public void setSolid(int number, boolean isSolid) {
    int i = place(number);
    if (i >= 0) {
      solid[i] = isSolid;
    }
  }

  /** Number of robots registered. */
  public int robotCount() {
    return robots.size();
  }

  /**
   * Casts a ray and stores the nearest hit (map, obstacle or another robot) in {@code out}, which
   * is reset first.
   *
   * @param ignoreRobot the number of the robot the ray starts from (-1 for none)
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
        if (numbers[i] != ignoreRobot && solid[i]) {
          robots.get(i).cast(ox, oy, dx, dy, out, numbers[i]);
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
   * {@code self} is the robot's number (-1 for none).
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

  /** Whether the robot at place {@code i} touches {@code candidate} (never robot {@code self}). */
  private boolean touchRobot(Footprint candidate, int self, int i, Contact out) {
    if (numbers[i] == self || !solid[i]) {
      return false;
    }
    Footprint other = robots.get(i);
    if (candidate.overlaps(other)) {
      other.offerContact(candidate, out, numbers[i]);
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
      if (numbers[robot] != ignore && solid[robot]) {
        robots.get(robot).cast(ox, oy, dx, dy, out, numbers[robot]);
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
