package org.jaria.classroom.wall;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.jaria.action.ArAction;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Fmt;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.GuardedAction;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Solutions;
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
  public Grade grade(StudentStreams student) {
    try (SimWorld world = SimWorld.ofLines(WALLS, START, SimOptions.builder().seed(3).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(START));
      try (StudentLink sim = StudentLink.connect(world, r, student, Map.of());
          PoseTrace trace = new PoseTrace(world, r)) {
        Optional<String> failed = sim.setUp();
        if (failed.isPresent()) {
          return Grading.setUpFailure(this, failed.get());
        }
        sim.runMillis(SECONDS * 1000L);
        List<Check> checks = new ArrayList<>();
        checks.add(GuardedAction.check(1, sim.call("fire")));
        double progress = progress(trace.x(trace.size() - 1), trace.y(trace.size() - 1));
        checks.add(alongFirst(progress, trace));
        checks.add(aroundCorner(progress, trace));
        checks.add(distanceKept(trace));
        checks.add(
            Check.of(
                "no collisions",
                2,
                !trace.everStalled(),
                "the robot never touched a wall",
                "your robot ran into something at "
                    + trace.firstStallWhere()
                    + " after "
                    + Fmt.seconds(trace.firstStallSeconds())
                    + ": slow down or turn away when a sonar reading gets short"));
        return new Grade(id(), checks);
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

  private static Check alongFirst(double progress, PoseTrace trace) {
    String name = "drives along the wall";
    if (progress >= ALONG_FIRST) {
      return Check.pass(name, 2, "got " + Fmt.dist(progress) + " along the course");
    }
    double moved = trace.distance(trace.size() - 1, START.x(), START.y());
    if (moved < 300) {
      return Check.fail(
          name,
          2,
          "your robot hardly moved ("
              + Fmt.dist(moved)
              + " in "
              + SECONDS
              + " s): does fire() return a desire with a forward velocity (desired.setVel(300))?");
    }
    return Check.fail(
        name,
        2,
        "your robot got only "
            + Fmt.dist(progress)
            + " along the wall in "
            + SECONDS
            + " s (it needs "
            + Fmt.dist(ALONG_FIRST)
            + "); it ended at "
            + Fmt.xy(trace.x(trace.size() - 1), trace.y(trace.size() - 1))
            + ": keep driving forward at 200 to 400 mm/s while you steer");
  }

  private static Check aroundCorner(double progress, PoseTrace trace) {
    String name = "turns the corner";
    if (progress >= AROUND_CORNER) {
      return Check.pass(
          name, 2, "went round the corner and " + Fmt.dist(progress - FIRST_LEG) + " on");
    }
    String hint =
        trace.everStalled() && trace.firstStallSeconds() > 0
            ? " It hit a wall at " + trace.firstStallWhere() + "."
            : "";
    return Check.fail(
        name,
        2,
        "your robot did not get "
            + Fmt.dist(AROUND_CORNER - FIRST_LEG)
            + " along the second wall after the corner at ("
            + Fmt.num(CORNER_X + 600, 0)
            + ", 0)."
            + hint
            + " When the wall ahead gets close (robot.checkRangeDevicesCurrentPolar(-20, 20)),"
            + " turn left until it is on your right again");
  }

  /** The share of samples away from the corner where the robot kept its distance. */
  private static Check distanceKept(PoseTrace trace) {
    String name = "keeps " + Fmt.dist(NEAR) + " to " + Fmt.dist(FAR) + " from the wall";
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
      return Check.fail(
          name, 3, "your robot did not drive far enough along the wall to measure its distance");
    }
    double share = (double) kept / counted;
    String detail =
        "it was within "
            + Fmt.dist(NEAR)
            + " to "
            + Fmt.dist(FAR)
            + " of the wall "
            + Fmt.num(100 * share, 0)
            + "% of the time; closest "
            + Fmt.dist(nearest)
            + " at "
            + Fmt.xy(trace.x(nearestAt), trace.y(nearestAt))
            + ", farthest "
            + Fmt.dist(farthest)
            + " at "
            + Fmt.xy(trace.x(farthestAt), trace.y(farthestAt));
    if (share >= KEEP_SHARE) {
      return Check.pass(name, 3, detail);
    }
    return Check.fail(
        name,
        3,
        detail
            + " (needs "
            + Fmt.num(100 * KEEP_SHARE, 0)
            + "%). Steer by the right-hand sonar (robot.checkRangeDevicesCurrentPolar(-100, -60)):"
            + " turn towards the wall when it is too far and away when too close, gently, so the"
            + " robot does not zig-zag");
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
