package org.jaria.classroom.link;

import java.util.Collections;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.function.IntPredicate;

/**
 * What the grading world refused from one student's robot link, and whether the robot's true path
 * did something no robot can: the grader's record for the report. {@link StudentLink} fills it in
 * (on the grading thread, the only one that touches it); the grader reads it once the assignment's
 * grading has returned.
 *
 * <p>Two lines of defence against a grade without driving: the link carries to the simulator only
 * what a real Pioneer accepts ({@link RobotCommands}), counting every packet it drops here; and the
 * robot's true pose is watched after every simulator step, so a jump no motor could make (however
 * it came about) is caught and costs the whole grade.
 */
public final class LinkAudit {

  /**
   * A jump of the robot's true pose within one simulator step, beyond what any robot can drive.
   *
   * @param seconds when, seconds of simulated time since the link connected
   * @param fromX where the robot was before the step, mm
   * @param fromY see fromX
   * @param toX where it was after the step, mm
   * @param toY see toX
   * @param mm how far it moved in the step
   * @param degrees how far it turned in the step
   */
  public record Jump(
      double seconds,
      double fromX,
      double fromY,
      double toX,
      double toY,
      double mm,
      double degrees) {}

  private final IntPredicate accepted;
  private final Map<String, Long> dropped = new TreeMap<>();
  private long garbageBytes;
  private int jumps;
  private Jump firstJump;

  /** An audit for a link that carries what a real Pioneer accepts ({@link RobotCommands}). */
  public LinkAudit() {
    this(RobotCommands::accepted);
  }

  private LinkAudit(IntPredicate accepted) {
    this.accepted = accepted;
  }

  /**
   * An audit for a link that carries the commands {@code accepted} lets through: only for testing
   * the second line of defence (the jump of the true path) on its own. The grader never uses it.
   */
  public static LinkAudit accepting(IntPredicate accepted) {
    return new LinkAudit(accepted);
  }

  /** Whether the link carries command {@code number} to the simulated robot. */
  boolean carries(int number) {
    return accepted.test(number);
  }

  /** Counts one packet the link did not carry to the simulator, under {@code what}. */
  public void dropped(String what) {
    dropped.merge(what, 1L, Long::sum);
  }

  /** Counts {@code n} bytes that were not part of any packet. */
  public void garbage(long n) {
    garbageBytes += n;
  }

  /** Records a jump of the true pose. */
  public void jump(Jump j) {
    jumps++;
    if (firstJump == null) {
      firstJump = j;
    }
  }

  /** The packets dropped, by command name (or why), sorted by name. */
  public Map<String, Long> dropped() {
    return Collections.unmodifiableMap(dropped);
  }

  /** How many packets were dropped in all. */
  public long droppedPackets() {
    return dropped.values().stream().mapToLong(Long::longValue).sum();
  }

  /** Bytes that were not part of any packet. */
  public long garbageBytes() {
    return garbageBytes;
  }

  /** How many steps the true pose jumped in. */
  public int jumps() {
    return jumps;
  }

  /** The first jump, if there was one. */
  public Optional<Jump> firstJump() {
    return Optional.ofNullable(firstJump);
  }

  /** Whether nothing was dropped and the path never jumped. */
  public boolean clean() {
    return dropped.isEmpty() && garbageBytes == 0 && jumps == 0;
  }
}
