package org.jaria.classroom.square;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.jaria.classroom.RobotProgram;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Fmt;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Programs;
import org.jaria.classroom.grading.Solutions;
import org.jaria.classroom.link.StudentContext;
import org.jaria.classroom.link.StudentLink;
import org.jaria.classroom.link.StudentSide;
import org.jaria.classroom.link.StudentStreams;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * Assignment 1: drive a 2 m square, counter-clockwise, with motion commands ({@code move}, {@code
 * setDeltaHeading}, waiting on {@code isMoveDone} and {@code isHeadingDone}), and stop where it
 * started.
 *
 * <p>Graded in an empty world on virtual time, from the simulator's true pose of the robot: each
 * corner must be passed within {@value #TOLERANCE} mm, in order, and the robot must end within
 * {@value #TOLERANCE} mm of its start, stopped.
 */
public final class SquareAssignment implements Assignment {

  /** The side of the square, mm. */
  public static final double SIDE = 2000;

  /** How close to each corner the robot must pass, mm. */
  public static final double TOLERANCE = 250;

  /** The most robot time the program may take. */
  static final Duration MAX_TIME = Duration.ofMinutes(2);

  private static final ArPose START = new ArPose(0, 0, 0);

  @Override
  public String id() {
    return "square";
  }

  @Override
  public String title() {
    return "Drive a 2 m square with motion commands";
  }

  @Override
  public Class<?> solutionType() {
    return RobotProgram.class;
  }

  @Override
  public String solutionClassName() {
    return "Square";
  }

  @Override
  public String solutionShape() {
    return "a public class that implements org.jaria.classroom.RobotProgram, with a public"
        + " constructor taking no arguments (e.g. 'public class Square implements RobotProgram')";
  }

  @Override
  public int points() {
    return 10;
  }

  @Override
  public StudentSide studentSide() {
    return new StudentSide() {
      private ArRobot robot;

      @Override
      public void setUp(StudentContext ctx) throws Solutions.SolutionException {
        RobotProgram program =
            Solutions.instantiate(
                ctx.solution(), RobotProgram.class, new Class<?>[0], new Object[0]);
        robot = ctx.robot();
        ctx.setProgram(program::run);
      }

      @Override
      public String call(String name) {
        return name.equals("actions") ? String.valueOf(robot.getActionList().size()) : "";
      }
    };
  }

  @Override
  public Grade grade(StudentStreams student) {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().seed(1).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(START));
      try (StudentLink sim = StudentLink.connect(world, r, student, Map.of());
          PoseTrace trace = new PoseTrace(world, r)) {
        Optional<String> failed = sim.setUp();
        if (failed.isPresent()) {
          return Grading.setUpFailure(this, failed.get());
        }
        List<Check> checks = new ArrayList<>();
        Programs.Ending end = Programs.run(sim, MAX_TIME, 1);
        checks.add(end.check());
        sim.runMillis(2000); // a program that returns while moving keeps moving
        List<Check> corners = corners(trace);
        checks.addAll(corners);
        checks.add(stopped(r));
        String actions = sim.call("actions");
        checks.add(
            Check.of(
                "motion commands only",
                1,
                actions.equals("0"),
                "no actions were added",
                "you added actions ("
                    + actions
                    + "); this assignment is about motion commands: use robot.move(mm) and"
                    + " robot.setDeltaHeading(deg) and wait for isMoveDone()/isHeadingDone()"));
        return new Grade(id(), corners.get(0).passed() ? checks : notEarned(checks));
      }
    }
  }

  /**
   * The checks of a robot that never reached the first corner: ending cleanly, standing still and
   * using motion commands are worth nothing if it never drove, so an empty program earns 0.
   */
  private static List<Check> notEarned(List<Check> checks) {
    List<Check> out = new ArrayList<>();
    for (Check c : checks) {
      out.add(
          c.passed()
              ? Check.fail(
                  c.name(),
                  c.points(),
                  c.message() + ", but this earns nothing while the robot never reaches corner 1")
              : c);
    }
    return out;
  }

  /** The three corners and the return to the start, in order. */
  private static List<Check> corners(PoseTrace trace) {
    double[][] corner = {{0, 0}, {SIDE, 0}, {SIDE, SIDE}, {0, SIDE}, {0, 0}};
    List<Check> checks = new ArrayList<>();
    int from = 0;
    int missedOne = 0;
    for (int k = 1; k <= 4; k++) {
      double cx = corner[k][0];
      double cy = corner[k][1];
      String name = k < 4 ? "corner " + k + " reached" : "back at the start";
      // the corner must be reached after leaving the previous one (the start counts once left)
      int leave = k == 4 ? firstFarFrom(trace, 0, 0, 2 * TOLERANCE, from) : from;
      if (leave < 0) {
        checks.add(
            Check.fail(
                name,
                1,
                "your robot never drove more than "
                    + Fmt.dist(2 * TOLERANCE)
                    + " away from where it started, so it cannot have driven the square"));
        continue;
      }
      int at = trace.firstWithin(cx, cy, TOLERANCE, leave);
      if (at >= 0) {
        int closest = closestWhileWithin(trace, cx, cy, at);
        checks.add(
            Check.pass(
                name,
                k < 4 ? 2 : 1,
                "passed within "
                    + Fmt.dist(trace.distance(closest, cx, cy))
                    + " of "
                    + Fmt.xy(cx, cy)
                    + " at "
                    + Fmt.seconds(trace.t(closest))));
        from = closest;
        continue;
      }
      if (missedOne > 0) {
        checks.add(
            Check.fail(
                name,
                k < 4 ? 2 : 1,
                "your robot did not get this far: fix corner " + missedOne + " first"));
        continue;
      }
      missedOne = k;
      checks.add(
          Check.fail(name, k < 4 ? 2 : 1, missed(trace, k, corner[k - 1], corner[k], leave)));
    }
    return checks;
  }

  /** The sample closest to (x, y) from {@code at} until the robot leaves the tolerance again. */
  private static int closestWhileWithin(PoseTrace trace, double x, double y, int at) {
    int best = at;
    for (int i = at; i < trace.size() && trace.distance(i, x, y) <= TOLERANCE; i++) {
      if (trace.distance(i, x, y) < trace.distance(best, x, y)) {
        best = i;
      }
    }
    return best;
  }

  private static int firstFarFrom(PoseTrace trace, double x, double y, double d, int from) {
    for (int i = from; i < trace.size(); i++) {
      if (trace.distance(i, x, y) > d) {
        return i;
      }
    }
    return -1;
  }

  /** Why the robot missed corner {@code k}, in words a student can act on. */
  private static String missed(PoseTrace trace, int k, double[] prev, double[] target, int from) {
    String what = k < 4 ? "corner " + k + " " + Fmt.xy(target[0], target[1]) : "the start (0, 0)";
    int i = trace.closestTo(target[0], target[1], from);
    double px = trace.x(i);
    double py = trace.y(i);
    double d = trace.distance(i, target[0], target[1]);
    double ux = (target[0] - prev[0]) / SIDE;
    double uy = (target[1] - prev[1]) / SIDE;
    double along = (px - prev[0]) * ux + (py - prev[1]) * uy;
    double aside = -(px - prev[0]) * uy + (py - prev[1]) * ux;
    StringBuilder sb = new StringBuilder("your robot never came within ");
    sb.append(Fmt.dist(TOLERANCE)).append(" of ").append(what).append("; ");
    boolean wentRight =
        k > 1 && k < 4 && trace.firstWithin(target[0], -target[1], 2 * TOLERANCE, from) >= 0;
    if (wentRight) {
      sb.append("it went to ").append(Fmt.xy(target[0], -target[1]));
      sb.append(" instead: it turned right. The square goes counter-clockwise: turn left,");
      sb.append(" robot.setDeltaHeading(90), and wait until robot.isHeadingDone()");
    } else if (Math.abs(aside) < 300 && along < 100 && along > -300 && k > 1) {
      sb.append("it never drove the side from corner ").append(k - 1).append(": after it, turn");
      sb.append(" 90 degrees left (robot.setDeltaHeading(90)), wait until robot.isHeadingDone(),");
      sb.append(" and drive the next ").append(Fmt.dist(SIDE));
    } else if (Math.abs(aside) < 300 && along < SIDE && along > -300) {
      sb.append("it stopped ").append(Fmt.dist(SIDE - along)).append(" short of it, at ");
      sb.append(Fmt.xy(px, py)).append(". Does every side drive the full ");
      sb.append(Fmt.dist(SIDE)).append(" and wait until robot.isMoveDone()?");
    } else if (Math.abs(aside) < 300 && along >= SIDE) {
      sb.append("it drove ").append(Fmt.dist(along - SIDE)).append(" past it, to ");
      sb.append(Fmt.xy(px, py)).append(": is a side longer than ").append(Fmt.dist(SIDE));
      sb.append(", or did it turn too late?");
    } else {
      sb.append("the closest it came was ").append(Fmt.dist(d)).append(", at ");
      sb.append(Fmt.xy(px, py)).append(". Check your turns: each is 90 degrees to the left,");
      sb.append(" and the robot must finish turning (isHeadingDone) before it drives");
    }
    return sb.toString();
  }

  private static Check stopped(SimRobot r) {
    double v = r.getVel();
    return Check.of(
        "stops at the end",
        1,
        Math.abs(v) < 20 && Math.abs(r.getRotVel()) < 5,
        "the robot was standing still after your program ended",
        "your robot was still moving ("
            + Fmt.num(v, 0)
            + " mm/s, "
            + Fmt.num(r.getRotVel(), 0)
            + " deg/s) two seconds after your program ended: wait for robot.isMoveDone() on the"
            + " last side, or call robot.stop(), before returning");
  }
}
