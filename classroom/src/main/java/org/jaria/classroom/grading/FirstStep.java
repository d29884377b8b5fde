package org.jaria.classroom.grading;

import java.util.ArrayList;
import java.util.List;

/**
 * The rule that a program which did nothing earns nothing. Checks such as "stops at the end",
 * "program ends", "no collisions" or "fire() runs without errors" pass for a robot that never
 * moved; they are worth their points only once the robot did the assignment's first real step
 * (reached the square's first corner, turned the wall's corner, stopped at the first goal, drove up
 * to the ball).
 */
public final class FirstStep {

  private FirstStep() {}

  /**
   * {@code checks} as they are if {@code done}; otherwise every passed check becomes a withheld one
   * whose message adds that it earns nothing until {@code step} ("the robot reaches corner 1",
   * already in the language of {@code t}).
   */
  public static List<Check> gate(List<Check> checks, boolean done, String step, Texts t) {
    if (done) {
      return List.copyOf(checks);
    }
    List<Check> out = new ArrayList<>();
    for (Check c : checks) {
      out.add(
          c.passed()
              ? Check.withheld(c.name(), c.points(), t.get("gate.notEarned", c.message(), step))
              : c);
    }
    return out;
  }
}
