package org.jaria.classroom.grading;

import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.robot.ArRobot;

/**
 * Wraps a student's action to remember the first exception its {@code fire} throws (the robot
 * switches a throwing action off and only logs it; the grader wants to tell the student).
 */
public final class GuardedAction extends ArAction {

  private final ArAction inner;
  private volatile Throwable failure;
  private final java.util.concurrent.atomic.AtomicLong fired =
      new java.util.concurrent.atomic.AtomicLong();

  /** Guards {@code inner}, under its name. */
  public GuardedAction(ArAction inner) {
    super(inner.getName(), inner.getDescription());
    this.inner = inner;
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    inner.setRobot(r);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    fired.incrementAndGet();
    try {
      return inner.fire(currentDesired);
    } catch (RuntimeException | Error e) {
      if (failure == null) {
        failure = e;
      }
      throw e;
    }
  }

  /** The first exception {@code fire} threw, or null. */
  public Throwable failure() {
    return failure;
  }

  /** How many times the action fired. */
  public long firedCount() {
    return fired.get();
  }

  /**
   * What the action did, as the student's side reports it to the grader: the times it fired, a tab,
   * and what it first threw (empty if nothing); {@link #check(int, String, Texts)} reads it.
   */
  public String report() {
    Throwable t = failure;
    return fired.get() + "\t" + (t == null ? "" : Solutions.describe(t));
  }

  /**
   * The check that the action never threw (worth {@code points}), from the student's side's {@link
   * #report()}, in the language of {@code t}.
   */
  public static Check check(int points, String report, Texts t) {
    String[] f = report.split("\t", 2);
    String fired = f[0].isEmpty() ? "0" : f[0];
    if (f.length < 2 || f[1].isEmpty()) {
      return Check.pass(t.get("fire.name"), points, t.get("fire.ok", fired));
    }
    return Check.fail(t.get("fire.name"), points, t.get("fire.threw", f[1]));
  }
}
