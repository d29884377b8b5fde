package dock;

import java.util.List;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Fmt;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Texts;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;

/** The dock's checks: plain functions over the robot's true path and its speed at the end. */
final class DockChecks {

  /** How close to the dock the robot counts as having reached it, mm. */
  static final double REACH = 300;

  /** How close to the dock the robot must stop, mm. */
  static final double PARK = 50;

  /** How far from the dock's heading the robot may face, degrees. */
  static final double FACING = 5;

  private DockChecks() {}

  /** The checks' names in {@code t}'s language, in the order a grade has them. */
  static List<String> names(Texts t) {
    return List.of(
        t.get("program.name"),
        t.get("dock.reach.name"),
        t.get("dock.parked.name", Fmt.dist(PARK)),
        t.get("dock.facing.name"),
        t.get("dock.stopped.name"),
        t.get("collisions.name"));
  }

  /**
   * Reaching the dock, parking within {@link #PARK}, facing its heading and standing still, from
   * the true path {@code trace} (its last sample is where the robot ended) and the speeds at the
   * end.
   */
  static List<Check> parking(PoseTrace trace, ArPose dock, double vel, double rotVel, Texts t) {
    int last = trace.size() - 1;
    Check reach;
    int at = trace.firstWithin(dock.x(), dock.y(), REACH, 0);
    if (at >= 0) {
      reach =
          Check.pass(
              t.get("dock.reach.name"),
              2,
              t.get("dock.reach.ok", Fmt.dist(REACH), Fmt.seconds(trace.t(at))));
    } else {
      int c = trace.closestTo(dock.x(), dock.y(), 0);
      reach =
          Check.fail(
              t.get("dock.reach.name"),
              2,
              t.get(
                  "dock.reach.missed",
                  Fmt.dist(REACH),
                  Fmt.xy(dock.x(), dock.y()),
                  Fmt.dist(trace.distance(c, dock.x(), dock.y())),
                  Fmt.xy(trace.x(c), trace.y(c))));
    }
    double off = trace.distance(last, dock.x(), dock.y());
    Check parked =
        Check.of(
            t.get("dock.parked.name", Fmt.dist(PARK)),
            3,
            off <= PARK,
            t.get("dock.parked.ok", Fmt.dist(off)),
            t.get(
                "dock.parked.off",
                Fmt.dist(off),
                Fmt.xy(trace.x(last), trace.y(last)),
                Fmt.dist(PARK)));
    double th = trace.th(last);
    double turn = Math.abs(ArMath.subAngle(th, dock.th()));
    Check facing =
        Check.of(
            t.get("dock.facing.name"),
            2,
            turn <= FACING,
            t.get("dock.facing.ok", Fmt.num(th, 0), Fmt.num(turn, 1)),
            t.get("dock.facing.off", Fmt.num(th, 0), Fmt.num(dock.th(), 0), Fmt.num(FACING, 0)));
    Check still =
        Check.of(
            t.get("dock.stopped.name"),
            1,
            Math.abs(vel) < 20 && Math.abs(rotVel) < 5,
            t.get("dock.stopped.ok"),
            t.get("dock.stopped.moving", Fmt.num(vel, 0), Fmt.num(rotVel, 0)));
    return List.of(reach, parked, facing, still);
  }

  /** No collisions along the way. */
  static Check collisions(PoseTrace trace, Texts t) {
    return Check.of(
        t.get("collisions.name"),
        1,
        !trace.everStalled(),
        t.get("collisions.none"),
        t.get("dock.collision", trace.firstStallWhere(), Fmt.seconds(trace.firstStallSeconds())));
  }
}
