package org.jaria.classroom.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.jaria.classroom.link.LinkAudit;

/**
 * The grader's last word on a grade, whatever the assignment: what the robot link refused becomes a
 * note, and a robot whose true path jumped (moved or turned in one step farther than any robot can)
 * earns nothing, each check saying why. Applied by the grader to every assignment's grade, built-in
 * or pack, so no assignment can forget it.
 */
public final class Integrity {

  private Integrity() {}

  /** {@code g} as the link's {@code audit} leaves it, in {@code t}'s language. */
  public static Grade apply(Grade g, LinkAudit audit, Texts t) {
    Grade out = g;
    if (!audit.dropped().isEmpty()) {
      List<String> parts = new ArrayList<>();
      for (Map.Entry<String, Long> e : audit.dropped().entrySet()) {
        parts.add(e.getKey() + " x" + e.getValue());
      }
      out =
          out.withNote(
              t.get("integrity.dropped", audit.droppedPackets(), String.join(", ", parts)));
    }
    if (audit.garbageBytes() > 0) {
      out = out.withNote(t.get("integrity.garbage", audit.garbageBytes()));
    }
    if (audit.firstJump().isPresent()) {
      LinkAudit.Jump j = audit.firstJump().get();
      String why =
          t.get(
              "integrity.jump",
              Fmt.dist(j.mm()),
              Fmt.num(j.degrees(), 0),
              Fmt.seconds(j.seconds()),
              Fmt.xy(j.fromX(), j.fromY()),
              Fmt.xy(j.toX(), j.toY()),
              audit.jumps());
      List<Check> checks = new ArrayList<>();
      for (Check c : out.checks()) {
        checks.add(
            c.passed()
                ? Check.withheld(c.name(), c.points(), t.get("integrity.notEarned", c.message()))
                : c);
      }
      out = out.withChecks(checks).withNote(why);
    }
    return out;
  }
}
