package org.jaria.classroom.square;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.jaria.classroom.RobotProgram;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.FirstStep;
import org.jaria.classroom.grading.Fmt;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Programs;
import org.jaria.classroom.grading.Solutions;
import org.jaria.classroom.grading.Texts;
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
  public List<String> checkNames(Texts t) {
    return List.of(
        t.get("program.name"),
        t.get("square.corner.name", 1),
        t.get("square.corner.name", 2),
        t.get("square.corner.name", 3),
        t.get("square.back.name"),
        t.get("square.stops.name"),
        t.get("square.motion.name"));
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
  public Grade grade(StudentStreams student, Texts t) {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().seed(1).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withStartPose(START));
      try (StudentLink sim = StudentLink.connect(world, r, student, Map.of());
          PoseTrace trace = new PoseTrace(world, r)) {
        Optional<String> failed = sim.setUp();
        if (failed.isPresent()) {
          return Grading.setUpFailure(this, failed.get(), t);
        }
        List<Check> checks = new ArrayList<>();
        Programs.Ending end = Programs.run(sim, MAX_TIME, 1, t);
        checks.add(end.check());
        sim.runMillis(2000); // a program that returns while moving keeps moving
        List<Check> corners = new ArrayList<>();
        for (Check c : corners(trace, t)) {
          corners.add(end.judged(c, t));
        }
        checks.addAll(corners);
        // "still moving after your program ended" means nothing for a program that did not end
        Check stopped = stopped(r, t);
        checks.add(
            end.finished()
                ? stopped
                : Check.withheld(stopped.name(), stopped.points(), end.notJudged(t)));
        String actions = sim.call("actions");
        checks.add(
            Check.of(
                t.get("square.motion.name"),
                1,
                actions.equals("0"),
                t.get("square.motion.ok"),
                t.get("square.motion.actions", actions)));
        return new Grade(
            id(), FirstStep.gate(checks, corners.get(0).passed(), t.get("step.square"), t));
      }
    }
  }

  /** The three corners and the return to the start, in order. */
  private static List<Check> corners(PoseTrace trace, Texts t) {
    double[][] corner = {{0, 0}, {SIDE, 0}, {SIDE, SIDE}, {0, SIDE}, {0, 0}};
    List<Check> checks = new ArrayList<>();
    int from = 0;
    int missedOne = 0;
    for (int k = 1; k <= 4; k++) {
      double cx = corner[k][0];
      double cy = corner[k][1];
      String name = k < 4 ? t.get("square.corner.name", k) : t.get("square.back.name");
      // the corner must be reached after leaving the previous one (the start counts once left)
      int leave = k == 4 ? firstFarFrom(trace, 0, 0, 2 * TOLERANCE, from) : from;
      if (leave < 0) {
        checks.add(Check.fail(name, 1, t.get("square.neverLeft", Fmt.dist(2 * TOLERANCE))));
        continue;
      }
      int at = trace.firstWithin(cx, cy, TOLERANCE, leave);
      if (at >= 0) {
        int closest = closestWhileWithin(trace, cx, cy, at);
        checks.add(
            Check.pass(
                name,
                k < 4 ? 2 : 1,
                t.get(
                    "square.passed",
                    Fmt.dist(trace.distance(closest, cx, cy)),
                    Fmt.xy(cx, cy),
                    Fmt.seconds(trace.t(closest)))));
        from = closest;
        continue;
      }
      if (missedOne > 0) {
        checks.add(Check.withheld(name, k < 4 ? 2 : 1, t.get("square.fixFirst", missedOne)));
        continue;
      }
      missedOne = k;
      checks.add(
          Check.fail(name, k < 4 ? 2 : 1, missed(trace, k, corner[k - 1], corner[k], leave, t)));
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
  private static String missed(
      PoseTrace trace, int k, double[] prev, double[] target, int from, Texts t) {
    String what =
        k < 4
            ? t.get("square.corner.what", k, Fmt.xy(target[0], target[1]))
            : t.get("square.start.what");
    int i = trace.closestTo(target[0], target[1], from);
    double px = trace.x(i);
    double py = trace.y(i);
    double d = trace.distance(i, target[0], target[1]);
    double ux = (target[0] - prev[0]) / SIDE;
    double uy = (target[1] - prev[1]) / SIDE;
    double along = (px - prev[0]) * ux + (py - prev[1]) * uy;
    double aside = -(px - prev[0]) * uy + (py - prev[1]) * ux;
    StringBuilder sb = new StringBuilder(t.get("square.missed", Fmt.dist(TOLERANCE), what));
    boolean wentRight =
        k > 1 && k < 4 && trace.firstWithin(target[0], -target[1], 2 * TOLERANCE, from) >= 0;
    if (wentRight) {
      sb.append(t.get("square.wentRight", Fmt.xy(target[0], -target[1])));
    } else if (Math.abs(aside) < 300 && along < 100 && along > -300 && k > 1) {
      sb.append(t.get("square.noSide", k - 1, Fmt.dist(SIDE)));
    } else if (Math.abs(aside) < 300 && along < SIDE && along > -300) {
      sb.append(t.get("square.short", Fmt.dist(SIDE - along), Fmt.xy(px, py), Fmt.dist(SIDE)));
    } else if (Math.abs(aside) < 300 && along >= SIDE) {
      sb.append(t.get("square.past", Fmt.dist(along - SIDE), Fmt.xy(px, py), Fmt.dist(SIDE)));
    } else {
      sb.append(t.get("square.closest", Fmt.dist(d), Fmt.xy(px, py)));
    }
    return sb.toString();
  }

  private static Check stopped(SimRobot r, Texts t) {
    double v = r.getVel();
    return Check.of(
        t.get("square.stops.name"),
        1,
        Math.abs(v) < 20 && Math.abs(r.getRotVel()) < 5,
        t.get("square.stops.ok"),
        t.get("square.stops.moving", Fmt.num(v, 0), Fmt.num(r.getRotVel(), 0)));
  }
}
