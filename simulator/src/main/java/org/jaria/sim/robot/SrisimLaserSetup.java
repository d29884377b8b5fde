package org.jaria.sim.robot;

/**
 * Tells SRISim's laser set-up commands from the ARCOS commands with the same numbers.
 *
 * <p>ARIA's {@code ArSimulatedLaser} sets the laser up with four commands in a fixed order: 36
 * start angle, 37 end angle, 38 increment (×100), 35 enable (1 plain, 2 extended packets). On ARCOS
 * the same numbers are GRIPPERVAL, GRIPREQUEST, GYROCALCW and ADSEL, and ARIA's {@code ArGripper}
 * sends GRIPREQUEST 2 whenever it starts. MobileSim reads every 35–38 as a laser command, so a
 * gripper request narrows the laser to −90..2° and ARIA prints "too many readings" 176 times. Here
 * a command counts as a laser command only as the next step of that sequence: 36 starts it, 37 and
 * 38 continue it, 35 ends it and applies the three settings together. Anything else among 35–38
 * keeps its ARCOS meaning (36 is both: the value also reaches the gripper).
 *
 * <p>Not thread-safe: the world thread uses it.
 */
public final class SrisimLaserSetup {

  /** What to do with one of the commands 35–38. */
  public enum Step {
    /** Not part of the laser set-up: execute the ARCOS command. */
    ARCOS,
    /** Remembered as part of the set-up; nothing to do yet. */
    PENDING,
    /** The set-up is complete: apply {@link #start}, {@link #end}, {@link #increment}, enable. */
    APPLY
  }

  private int next;
  private int start;
  private int end;
  private int increment;

  /** Forgets a half-finished set-up (a new session). */
  public void reset() {
    next = 0;
  }

  /** Feeds command {@code command} (35..38) with its argument; says what it is. */
  public Step accept(int command, int arg) {
    if (command == 36) {
      start = arg;
      next = 37;
      return Step.PENDING;
    }
    if (command != next) {
      next = 0;
      return Step.ARCOS;
    }
    switch (command) {
      case 37 -> {
        end = arg;
        next = 38;
        return Step.PENDING;
      }
      case 38 -> {
        increment = arg;
        next = 35;
        return Step.PENDING;
      }
      default -> {
        next = 0;
        return Step.APPLY;
      }
    }
  }

  /** Start angle of the completed set-up, degrees. */
  public int start() {
    return start;
  }

  /** End angle of the completed set-up, degrees. */
  public int end() {
    return end;
  }

  /** Increment of the completed set-up, hundredths of a degree. */
  public int increment() {
    return increment;
  }
}
