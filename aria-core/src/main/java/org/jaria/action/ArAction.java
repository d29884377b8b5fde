package org.jaria.action;

import java.util.function.Supplier;
import org.jaria.robot.ArRobot;

/**
 * A behaviour: once per cycle the robot asks every active action what it wants ({@link #fire}), and
 * the resolver combines the answers by priority (ARIA's {@code ArAction}).
 *
 * <p>To write one, extend this class and implement {@code fire}: look at the robot (its pose,
 * speeds, range devices), fill in this action's {@link ArActionDesired} — only the channels it
 * cares about — and return it; return {@code null} to want nothing this cycle. {@code fire} runs on
 * the robot's cycle thread with the robot locked, so it may read the robot freely but must return
 * quickly.
 *
 * <p><b>Locking.</b> The robot's lock is the only lock an action needs: {@code fire} always runs
 * holding it, so an action's setters and getters, which other threads call, take the same lock with
 * {@link #locked(Runnable)} or {@link #lockedGet(Supplier)} and can never run in the middle of a
 * {@code fire}. Fields an action shares between {@code fire} and such methods need no lock of their
 * own (ARIA's convention too: lock the robot to change a running action).
 *
 * <pre>{@code
 * class Forward extends ArAction {
 *   private final ArActionDesired desired = new ArActionDesired();
 *   Forward() { super("forward", "drives forward at 300 mm/s"); }
 *   public ArActionDesired fire(ArActionDesired current) {
 *     desired.reset();
 *     desired.setVel(300);
 *     return desired;
 *   }
 * }
 * robot.addAction(new Forward(), 50);
 * }</pre>
 */
public abstract class ArAction {

  private final String name;
  private final String description;
  private volatile boolean active = true;
  private volatile ArRobot robot;

  /** An action with a name (unique on its robot) and a description for people. */
  protected ArAction(String name, String description) {
    this.name = name;
    this.description = description;
  }

  /** An action with a name and no description. */
  protected ArAction(String name) {
    this(name, "");
  }

  /**
   * Says what this action wants this cycle.
   *
   * @param currentDesired what higher-priority actions have asked for so far (read only)
   * @return this action's desire, or null for none
   */
  public abstract ArActionDesired fire(ArActionDesired currentDesired);

  /** Called when the action is added to a robot; override to set up (call super). */
  public void setRobot(ArRobot r) {
    robot = r;
  }

  /** The robot this action drives, or null before it is added. */
  public ArRobot getRobot() {
    return robot;
  }

  /**
   * Runs {@code body} holding the robot's lock, the lock the cycle holds while actions fire (or, if
   * the action has no robot yet, so nothing fires it, just runs it). The lock is reentrant, so
   * {@code body} may be called from {@code fire} or from code that already holds the robot's lock.
   */
  protected final void locked(Runnable body) {
    ArRobot r = robot;
    if (r == null) {
      body.run();
      return;
    }
    r.lock();
    try {
      body.run();
    } finally {
      r.unlock();
    }
  }

  /** As {@link #locked(Runnable)}, for a body that returns a value. */
  protected final <T> T lockedGet(Supplier<T> body) {
    ArRobot r = robot;
    if (r == null) {
      return body.get();
    }
    r.lock();
    try {
      return body.get();
    } finally {
      r.unlock();
    }
  }

  /** Makes the action take part. Actions start active. */
  public void activate() {
    active = true;
  }

  /** Stops the action from taking part until activated again. */
  public void deactivate() {
    active = false;
  }

  /** Whether the action takes part. */
  public boolean isActive() {
    return active;
  }

  /** The action's name. */
  public String getName() {
    return name;
  }

  /** What the action does. */
  public String getDescription() {
    return description;
  }

  @Override
  public String toString() {
    return name + (active ? "" : " (inactive)");
  }
}
