package org.jaria.classroom.ball;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionLimiterForwards;
import org.jaria.acts.ArACTS_1_2;
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
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;

/**
 * Assignment 4: follow a coloured ball with ACTS. The student writes an {@link ArAction} that reads
 * the blobs ACTS finds on channel 1 (trained on the ball's red) and drives towards the largest. The
 * grader adds, as the thesis's program does, a forward speed limiter above it and a "stop" action
 * below it.
 *
 * <p>Three phases on the simulator: drive up to a ball 2.5 m ahead; keep up with it while it rolls
 * 2 m sideways; stop when it disappears.
 */
public final class BallAssignment implements Assignment {

  /** How close (robot centre to ball edge) the robot must get, mm. */
  public static final double CLOSE = 900;

  /** How far the ball may get from the robot while it rolls, mm. */
  public static final double KEEP_UP = 1200;

  @Override
  public String id() {
    return "ball";
  }

  @Override
  public String title() {
    return "Follow a coloured ball with ACTS";
  }

  @Override
  public Class<?> solutionType() {
    return ArAction.class;
  }

  @Override
  public String solutionClassName() {
    return "BallFollower";
  }

  @Override
  public String solutionShape() {
    return "a public class that extends org.jaria.action.ArAction, with a public constructor"
        + " taking the ACTS client (e.g. 'public BallFollower(ArACTS_1_2 acts)')";
  }

  @Override
  public int points() {
    return 10;
  }

  @Override
  public List<String> checkNames(Texts t) {
    return List.of(
        t.get("ball.approach.name"),
        t.get("ball.follow.name"),
        t.get("ball.stops.name"),
        t.get("fire.name"),
        t.get("collisions.name"));
  }

  @Override
  public StudentSide studentSide() {
    return new StudentSide() {
      private GuardedAction guarded;

      @Override
      public void setUp(StudentContext ctx) throws Solutions.SolutionException {
        ArRobot robot = ctx.robot();
        ArACTS_1_2 acts = new ArACTS_1_2(ctx.clock());
        acts.setReadTimeouts(0, 0); // lockstep: the reply comes on the next tick, never wait
        if (!acts.openPort(robot, ctx.channel("acts"))) {
          throw new IllegalStateException("ACTS did not open: " + acts.getOpenMessage());
        }
        ArAction action =
            Solutions.instantiate(
                ctx.solution(), ArAction.class, new Class<?>[] {ArACTS_1_2.class}, acts);
        guarded = new GuardedAction(action);
        robot.addAction(new ArActionLimiterForwards("speed limiter near", 350, 800, 200), 7);
        robot.addAction(guarded, 3);
        robot.addAction(new ArActionConstantVelocity("stop", 0), 1);
        robot.enableMotors();
      }

      @Override
      public String call(String name) {
        return name.equals("fire") && guarded != null ? guarded.report() : "";
      }
    };
  }

  @Override
  public Grade grade(StudentStreams student, Texts t) {
    try (BallScene scene = new BallScene(11, 2500, 400);
        StudentLink sim =
            StudentLink.connect(
                scene.world, scene.simRobot, student, Map.of("acts", scene.actsEnd))) {
      Optional<String> failed = sim.setUp();
      if (failed.isPresent()) {
        return Grading.setUpFailure(this, failed.get(), t);
      }
      try (PoseTrace trace = new PoseTrace(scene.world, scene.simRobot)) {
        List<Check> checks = new ArrayList<>();
        boolean close = sim.runUntil(() -> scene.distanceToBall() < CLOSE, Duration.ofSeconds(30));
        checks.add(approach(close, scene, t));
        checks.add(follow(close, scene, sim, t));
        checks.add(stopsWhenLost(scene, sim, t));
        checks.add(GuardedAction.check(1, sim.call("fire"), t));
        checks.add(
            Check.of(
                t.get("collisions.name"),
                1,
                !trace.everStalled(),
                t.get("ball.collisions.none"),
                t.get(
                    "ball.collision",
                    trace.firstStallWhere(),
                    Fmt.seconds(trace.firstStallSeconds()))));
        return new Grade(id(), FirstStep.gate(checks, close, t.get("step.ball"), t));
      }
    }
  }

  private static Check approach(boolean close, BallScene scene, Texts t) {
    String name = t.get("ball.approach.name");
    if (close) {
      return Check.pass(name, 3, t.get("ball.approach.ok", Fmt.dist(CLOSE)));
    }
    double v = scene.simRobot.getVel();
    return Check.fail(
        name,
        3,
        t.get(
            "ball.approach.failed",
            Fmt.dist(scene.distanceToBall()),
            Fmt.dist(scene.startDistance),
            Fmt.num(v, 0)));
  }

  private static Check follow(boolean close, BallScene scene, StudentLink sim, Texts t) {
    String name = t.get("ball.follow.name");
    if (!close) {
      return Check.withheld(name, 3, t.get("ball.follow.notTried"));
    }
    double x = scene.ball().x();
    double y = scene.ball().y();
    ArPose before = scene.simRobot.getTruePose();
    double heading = Math.toRadians(before.th());
    for (int step = 1; step <= 100; step++) {
      double d = 20.0 * step; // 100 mm/s to the robot's left
      scene.moveBall(x - d * Math.sin(heading), y + d * Math.cos(heading));
      sim.runMillis(200);
      if (scene.distanceToBall() > KEEP_UP) {
        return Check.fail(
            name,
            3,
            t.get(
                "ball.follow.lost",
                Fmt.dist(scene.distanceToBall()),
                Fmt.seconds(step * 0.2),
                Fmt.dist(KEEP_UP)));
      }
    }
    double moved = scene.simRobot.getTruePose().findDistanceTo(before);
    if (moved < 1000) {
      return Check.fail(name, 3, t.get("ball.follow.notDriving", Fmt.dist(moved)));
    }
    return Check.pass(name, 3, t.get("ball.follow.ok", Fmt.dist(KEEP_UP), Fmt.dist(moved)));
  }

  private static Check stopsWhenLost(BallScene scene, StudentLink sim, Texts t) {
    scene.removeBall();
    sim.runMillis(3000);
    double v = scene.simRobot.getVel();
    return Check.of(
        t.get("ball.stops.name"),
        2,
        Math.abs(v) < 30,
        t.get("ball.stops.ok"),
        t.get("ball.stops.failed", Fmt.num(v, 0)));
  }
}
