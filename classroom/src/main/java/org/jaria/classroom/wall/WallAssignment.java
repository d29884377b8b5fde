package org.jaria.classroom.wall;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.jaria.action.ArAction;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.FirstStep;
import org.jaria.classroom.grading.Fmt;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.GuardedAction;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Solutions;
import org.jaria.classroom.grading.Texts;
import org.jaria.classroom.link.StudentContext;
import org.jaria.classroom.link.StudentLink;
import org.jaria.classroom.link.StudentSide;
import org.jaria.classroom.link.StudentStreams;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSonarDevice;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * Assignment 2: wall following with a custom action. The student writes an {@link ArAction} that
 * keeps a wall on the robot's right at about 600 mm while driving forward, and turns left where the
 * wall meets another one.
 *
 * <p>The course: a 9 m wall along y = 0 and, at its east end, a 14 m wall going north. The robot
 * starts 600 mm from the first wall, facing along it, with only the student's action and the sonar;
 * it runs for {@value #SECONDS} s of robot time.
 */
public final class WallAssignment implements Assignment {

  /** How long the action drives, seconds of robot time. */
  public static final int SECONDS = 60;

  /** The closest and farthest the robot's centre may be from the wall, mm. */
  public static final double NEAR = 350;

  /** See {@link #NEAR}. */
  public static final double FAR = 1000;

  /** The share of the time the robot must be within [NEAR, FAR] of the wall. */
  public static final double KEEP_SHARE = 0.9;

  /** The walls of the course. */
  public static final List<ArLineSegment> WALLS =
      List.of(new ArLineSegment(-1000, 0, 8000, 0), new ArLineSegment(8000, 0, 8000, 14000));

  /** Where the robot starts: 600 mm from the wall, facing along it (the wall on its right). */
  public static final ArPose START = new ArPose(0, 600, 0);

  // The course's centre line, to measure progress along it: along the first wall to the corner,
  // then up the second.
  private static final double CORNER_X = 7400;
  private static final double FIRST_LEG = CORNER_X - START.x();
  private static final double ALONG_FIRST = 6000;
  private static final double AROUND_CORNER = FIRST_LEG + 1600;

  @Override
  public String id() {
    return "wall";
  }

  @Override
  public String title() {
    return "Follow a wall with a custom action";
  }

  @Override
  public Class<?> solutionType() {
    return ArAction.class;
  }

  @Override
  public String solutionClassName() {
    return "WallFollower";
  }

  @Override
  public String solutionShape() {
    return "a public class that extends org.jaria.action.ArAction, with a public constructor"
        + " taking no arguments (e.g. 'public class WallFollower extends ArAction')";
  }

  @Override
  public int points() {
    return 10;
  }

  @Override
  public List<String> checkNames(Texts t) {
    return List.of(
        t.get("fire.name"),
        t.get("wall.along.name"),
        t.get("wall.corner.name"),
        t.get("wall.kept.name", Fmt.dist(NEAR), Fmt.dist(FAR)),
        t.get("collisions.name"));
  }

  @Override
  public StudentSide studentSide() {
    return new StudentSide() {
      private GuardedAction guarded;

      @Override
      public void setUp(StudentContext ctx) throws Solutions.SolutionException {
        ArAction action =
            Solutions.instantiate(ctx.solution(), ArAction.class, new Class<?>[0], new Object[0]);
        guarded = new GuardedAction(action);
        ctx.robot().addRangeDevice(new ArSonarDevice());
        ctx.robot().addAction(guarded, 50);
        ctx.robot().enableMotors();
      }

      @Override
      public String call(String name) {
        return name.equals("fire") && guarded != null ? guarded.report() : "";
      }
    };
  }

  @Override
  public Grade grade(StudentStreams student, Texts t) {
    try (SimWorld world = SimWorld.ofLines(WALLS, START, SimOptions.builder().seed(3).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(START));
      try (StudentLink sim = StudentLink.connect(world, r, student, Map.of());
          PoseTrace trace = new PoseTrace(world, r)) {
        Optional<String> failed = sim.setUp();
        if (failed.isPresent()) {
          return Grading.setUpFailure(this, failed.get(), t);
        }
        sim.runMillis(SECONDS * 1000L);
        List<Check> checks = new ArrayList<>();
        checks.add(GuardedAction.check(1, sim.call("fire"), t));
        double progress = progress(trace.x(trace.size() - 1), trace.y(trace.size() - 1));
        checks.add(alongFirst(progress, trace, t));
        Check corner = aroundCorner(progress, trace, t);
        checks.add(corner);
        checks.add(distanceKept(trace, t));
        checks.add(
            Check.of(
                t.get("collisions.name"),
                2,
                !trace.everStalled(),
                t.get("collisions.none"),
                t.get(
                    "wall.collision",
                    trace.firstStallWhere(),
                    Fmt.seconds(trace.firstStallSeconds()))));
        // Driving straight on along the first wall (what the starter does) keeps the distance and
        // gets far along it without following anything: only turning the corner shows following.
        return new Grade(id(), FirstStep.gate(checks, corner.passed(), t.get("step.wall"), t));
      }
    }
  }

  /** How far along the course's centre line (first wall, then second) the point is, mm. */
  static double progress(double x, double y) {
    double t1 = Math.max(0, Math.min(FIRST_LEG, x - START.x()));
    double d1 = Math.hypot(x - (START.x() + t1), y - START.y());
    double t2 = Math.max(0, y - START.y());
    double d2 = Math.hypot(x - CORNER_X, y - (START.y() + t2));
    return d1 <= d2 ? t1 : FIRST_LEG + t2;
  }

  private static Check alongFirst(double progress, PoseTrace trace, Texts t) {
    String name = t.get("wall.along.name");
    if (progress >= ALONG_FIRST) {
      return Check.pass(name, 2, t.get("wall.along.ok", Fmt.dist(progress)));
    }
    double moved = trace.distance(trace.size() - 1, START.x(), START.y());
    if (moved < 300) {
      return Check.fail(name, 2, t.get("wall.along.hardlyMoved", Fmt.dist(moved), SECONDS));
    }
    return Check.fail(
        name,
        2,
        t.get(
            "wall.along.short",
            Fmt.dist(progress),
            SECONDS,
            Fmt.dist(ALONG_FIRST),
            Fmt.xy(trace.x(trace.size() - 1), trace.y(trace.size() - 1))));
  }

  private static Check aroundCorner(double progress, PoseTrace trace, Texts t) {
    String name = t.get("wall.corner.name");
    if (progress >= AROUND_CORNER) {
      return Check.pass(name, 2, t.get("wall.corner.ok", Fmt.dist(progress - FIRST_LEG)));
    }
    String hint =
        trace.everStalled() && trace.firstStallSeconds() > 0
            ? t.get("wall.corner.hitAt", trace.firstStallWhere())
            : "";
    return Check.fail(
        name,
        2,
        t.get(
            "wall.corner.failed",
            Fmt.dist(AROUND_CORNER - FIRST_LEG),
            Fmt.num(CORNER_X + 600, 0),
            hint));
  }

  /** The share of samples away from the corner where the robot kept its distance. */
  private static Check distanceKept(PoseTrace trace, Texts t) {
    String name = t.get("wall.kept.name", Fmt.dist(NEAR), Fmt.dist(FAR));
    int counted = 0;
    int kept = 0;
    double nearest = Double.POSITIVE_INFINITY;
    double farthest = 0;
    int nearestAt = -1;
    int farthestAt = -1;
    for (int i = 0; i < trace.size(); i++) {
      double p = progress(trace.x(i), trace.y(i));
      boolean cornerZone = p > FIRST_LEG - 1400 && p < FIRST_LEG + 1200;
      if (p < 500 || cornerZone) {
        continue;
      }
      double d = wallDistance(trace.x(i), trace.y(i));
      counted++;
      if (d >= NEAR && d <= FAR) {
        kept++;
      }
      if (d < nearest) {
        nearest = d;
        nearestAt = i;
      }
      if (d > farthest) {
        farthest = d;
        farthestAt = i;
      }
    }
    if (counted < 100) {
      return Check.fail(name, 3, t.get("wall.kept.tooShort"));
    }
    double share = (double) kept / counted;
    String detail =
        t.get(
            "wall.kept.detail",
            Fmt.dist(NEAR),
            Fmt.dist(FAR),
            Fmt.num(100 * share, 0),
            Fmt.dist(nearest),
            Fmt.xy(trace.x(nearestAt), trace.y(nearestAt)),
            Fmt.dist(farthest),
            Fmt.xy(trace.x(farthestAt), trace.y(farthestAt)));
    if (share >= KEEP_SHARE) {
      return Check.pass(name, 3, detail);
    }
    return Check.fail(name, 3, t.get("wall.kept.failed", detail, Fmt.num(100 * KEEP_SHARE, 0)));
  }

  /** Distance from (x, y) to the nearest wall of the course, mm. */
  static double wallDistance(double x, double y) {
    double best = Double.POSITIVE_INFINITY;
    for (ArLineSegment w : WALLS) {
      double dx = w.x2() - w.x1();
      double dy = w.y2() - w.y1();
      double t = ((x - w.x1()) * dx + (y - w.y1()) * dy) / (dx * dx + dy * dy);
      t = Math.max(0, Math.min(1, t));
      best = Math.min(best, Math.hypot(x - (w.x1() + t * dx), y - (w.y1() + t * dy)));
    }
    return best;
  }
}
