package org.jaria.classroom.goals;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.arnl.ArActionLost;
import org.jaria.arnl.ArActionSlowDownWhenNotCertain;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.classroom.NavigationProgram;
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
import org.jaria.map.ArMap;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * Assignment 3: go to named goals with navigation. The student's {@link NavigationProgram} gets a
 * robot already localized at the home of the bundled office map and the path planning task, and
 * must visit the goals in the order given, waiting for each to be reached.
 *
 * <p>Graded from the simulator's true pose: the robot must stop within {@value #TOLERANCE} mm of
 * each goal, in order. Odometry drifts as on a real robot, so the sonar localization matters.
 */
public final class GoalsAssignment implements Assignment {

  /** The goals, in order. */
  public static final List<String> GOALS = List.of("Lab Entrance", "Corridor West");

  /** How close to a goal the robot must stop, mm. */
  public static final double TOLERANCE = 400;

  static final Duration MAX_TIME = Duration.ofMinutes(3);

  private static final long SEED = 5;

  @Override
  public String id() {
    return "goals";
  }

  @Override
  public String title() {
    return "Go to named goals with localization and path planning";
  }

  @Override
  public Class<?> solutionType() {
    return NavigationProgram.class;
  }

  @Override
  public String solutionClassName() {
    return "GoalTour";
  }

  @Override
  public String solutionShape() {
    return "a public class that implements org.jaria.classroom.NavigationProgram, with a public"
        + " constructor taking no arguments (e.g. 'public class GoalTour implements"
        + " NavigationProgram')";
  }

  @Override
  public int points() {
    return 10;
  }

  @Override
  public List<String> checkNames(Texts t) {
    List<String> names = new ArrayList<>();
    names.add(t.get("program.name"));
    for (int k = 0; k < GOALS.size(); k++) {
      names.add(t.get("goals.goal.name", k + 1, GOALS.get(k)));
    }
    names.add(t.get("collisions.name"));
    return names;
  }

  @Override
  public StudentSide studentSide() {
    return new StudentSide() {
      private ArSonarLocalizationTask loc;
      private final AtomicInteger interrupted = new AtomicInteger();

      @Override
      public void setUp(StudentContext ctx) throws Solutions.SolutionException {
        NavigationProgram program =
            Solutions.instantiate(
                ctx.solution(), NavigationProgram.class, new Class<?>[0], new Object[0]);
        ArRobot robot = ctx.robot();
        ArMap map = ArMap.loadBundled("office");
        ArSonarDevice sonar = new ArSonarDevice();
        robot.addRangeDevice(sonar);
        // Both tasks live as long as this JVM, which ends with the grading.
        loc =
            ArSonarLocalizationTask.builder(robot, map)
                .sonar(sonar)
                .mode(ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS)
                .seed(SEED)
                .build();
        ArPathPlanningTask path =
            ArPathPlanningTask.builder(robot, map)
                .sonar(sonar)
                .mode(ArPathPlanningTask.PlanMode.SYNCHRONOUS)
                .build();
        path.getPathPlanActionGroup().addAction(new ArActionSlowDownWhenNotCertain(loc), 140);
        path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
        path.addGoalInterruptedCB(g -> interrupted.incrementAndGet());
        robot.enableMotors();
        ctx.setProgram(rb -> program.run(rb, path, GOALS));
      }

      @Override
      public String call(String name) {
        return switch (name) {
          case "localize" -> String.valueOf(loc.localizeRobotAtHomeBlocking());
          case "interrupted" -> String.valueOf(interrupted.get());
          default -> "";
        };
      }
    };
  }

  @Override
  public Grade grade(StudentStreams student, Texts t) {
    ArMap map = ArMap.loadBundled("office");
    SimOptions options =
        SimOptions.builder().seed(SEED).odometryError(OdometryError.random(0.02, 0.02)).build();
    try (SimWorld world = SimWorld.create(map, options)) {
      SimRobot r = world.addRobot("p3dx-sh");
      try (StudentLink sim = StudentLink.connect(world, r, student, Map.of())) {
        Optional<String> failed = sim.setUp();
        if (failed.isPresent()) {
          return Grading.setUpFailure(this, failed.get(), t);
        }
        sim.runMillis(1500);
        if (!sim.call("localize").equals("true")) {
          return new Grade(
              id(),
              List.of(
                  Check.fail(
                      t.get("goals.localized.name"), points(), t.get("goals.localized.failed"))));
        }
        try (PoseTrace trace = new PoseTrace(world, r)) {
          List<Check> checks = new ArrayList<>();
          Programs.Ending end = Programs.run(sim, MAX_TIME, 2, t);
          checks.add(end.check());
          sim.runMillis(5000);
          int interrupted = sim.call("interrupted").matches("0*") ? 0 : 1;
          List<Check> goals = new ArrayList<>();
          for (Check c : goals(map, trace, interrupted, t)) {
            goals.add(end.judged(c, t));
          }
          checks.addAll(goals);
          checks.add(
              Check.of(
                  t.get("collisions.name"),
                  2,
                  !trace.everStalled(),
                  t.get("collisions.none"),
                  t.get(
                      "goals.collision",
                      trace.firstStallWhere(),
                      Fmt.seconds(trace.firstStallSeconds()))));
          return new Grade(
              id(),
              FirstStep.gate(checks, goals.get(0).passed(), t.get("step.goals", GOALS.get(0)), t));
        }
      }
    }
  }

  private List<Check> goals(ArMap map, PoseTrace trace, int interrupted, Texts t) {
    List<Check> checks = new ArrayList<>();
    int from = 0;
    boolean previousReached = false;
    for (int k = 0; k < GOALS.size(); k++) {
      String goal = GOALS.get(k);
      ArPose p = map.findMapObject(goal).orElseThrow().pose();
      String name = t.get("goals.goal.name", k + 1, goal);
      int at = trace.firstStopWithin(p.x(), p.y(), TOLERANCE, 30, from);
      if (at >= 0) {
        checks.add(
            Check.pass(
                name,
                3,
                t.get(
                    "goals.goal.ok",
                    Fmt.dist(trace.distance(at, p.x(), p.y())),
                    Fmt.seconds(trace.t(at)))));
        from = at;
        previousReached = true;
        continue;
      }
      int closest = trace.closestTo(p.x(), p.y(), from);
      StringBuilder msg =
          new StringBuilder(
              t.get(
                  "goals.goal.missed",
                  Fmt.dist(TOLERANCE),
                  goal,
                  Fmt.xy(p.x(), p.y()),
                  previousReached ? t.get("goals.goal.afterPrevious") : "",
                  Fmt.dist(trace.distance(closest, p.x(), p.y()))));
      msg.append(interrupted > 0 ? t.get("goals.goal.replaced") : t.get("goals.goal.askFor", goal));
      checks.add(Check.fail(name, 3, msg.toString()));
      previousReached = false;
    }
    return checks;
  }
}
