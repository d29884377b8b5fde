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
  public Grade grade(StudentStreams student) {
    try (BallScene scene = new BallScene(11, 2500, 400);
        StudentLink sim =
            StudentLink.connect(
                scene.world, scene.simRobot, student, Map.of("acts", scene.actsEnd))) {
      Optional<String> failed = sim.setUp();
      if (failed.isPresent()) {
        return Grading.setUpFailure(this, failed.get());
      }
      try (PoseTrace trace = new PoseTrace(scene.world, scene.simRobot)) {
        List<Check> checks = new ArrayList<>();
        boolean close = sim.runUntil(() -> scene.distanceToBall() < CLOSE, Duration.ofSeconds(30));
        checks.add(approach(close, scene));
        checks.add(follow(close, scene, sim));
        checks.add(stopsWhenLost(scene, sim));
        checks.add(GuardedAction.check(1, sim.call("fire")));
        checks.add(
            Check.of(
                "no collisions",
                1,
                !trace.everStalled(),
                "the robot never ran into anything",
                "your robot ran into something at "
                    + trace.firstStallWhere()
                    + " after "
                    + Fmt.seconds(trace.firstStallSeconds())));
        return new Grade(id(), checks);
      }
    }
  }

  private static Check approach(boolean close, BallScene scene) {
    String name = "drives up to the ball";
    if (close) {
      return Check.pass(name, 3, "got within " + Fmt.dist(CLOSE) + " of the ball");
    }
    double v = scene.simRobot.getVel();
    return Check.fail(
        name,
        3,
        "after 30 s your robot was still "
            + Fmt.dist(scene.distanceToBall())
            + " from the ball (it started "
            + Fmt.dist(scene.startDistance)
            + " away, the ball 400 mm to its left) and moving at "
            + Fmt.num(v, 0)
            + " mm/s: when acts.getNumBlobs(1) > 0, set a forward velocity (desired.setVel(200))"
            + " and turn towards the largest blob: blob.getXCG() below 80 (the image is 160"
            + " pixels wide) means it is to the left, turn with a positive"
            + " desired.setDeltaHeading");
  }

  private static Check follow(boolean close, BallScene scene, StudentLink sim) {
    String name = "follows the ball as it rolls";
    if (!close) {
      return Check.fail(name, 3, "not tried: the robot never got close to the ball");
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
            "the ball rolled to your robot's left at 100 mm/s and got "
                + Fmt.dist(scene.distanceToBall())
                + " away after "
                + Fmt.seconds(step * 0.2)
                + " (allowed: "
                + Fmt.dist(KEEP_UP)
                + "): keep turning towards the blob while you drive (a turn proportional to how"
                + " far its centre is from the middle of the image); and if ACTS lost the ball"
                + " because the robot got too close, slow down as the blob nears the bottom of"
                + " the image (blob.getYCG() close to 120)");
      }
    }
    double moved = scene.simRobot.getTruePose().findDistanceTo(before);
    if (moved < 1000) {
      return Check.fail(
          name,
          3,
          "the robot moved only "
              + Fmt.dist(moved)
              + " while the ball rolled 2 m: keep driving towards it, not only turning");
    }
    return Check.pass(
        name, 3, "stayed within " + Fmt.dist(KEEP_UP) + " and moved " + Fmt.dist(moved));
  }

  private static Check stopsWhenLost(BallScene scene, StudentLink sim) {
    scene.removeBall();
    sim.runMillis(3000);
    double v = scene.simRobot.getVel();
    return Check.of(
        "stops when the ball is gone",
        2,
        Math.abs(v) < 30,
        "stopped within 3 s of losing the ball",
        "3 s after the ball disappeared your robot was still driving at "
            + Fmt.num(v, 0)
            + " mm/s: when ACTS has seen no blob for a while (say a second), return null from"
            + " fire() so the lower-priority stop action takes over");
  }
}
