package org.jaria.action;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.jaria.robot.ArRobot;

/**
 * A set of actions switched on and off together (ARIA's {@code ArActionGroup}). Adding an action to
 * a group also adds it to the group's robot; {@link #activate()} and {@link #deactivate()} then act
 * on the whole set, and {@link #activateExclusive()} first deactivates every other action of the
 * robot, so that exactly this behaviour drives.
 *
 * <pre>{@code
 * ArActionGroupWander wander = new ArActionGroupWander(robot);
 * ArActionGroupStop stop = new ArActionGroupStop(robot);
 * wander.activateExclusive();   // roam
 * stop.activateExclusive();     // and later stand still
 * }</pre>
 *
 * <p>The predefined groups ({@link ArActionGroupStop}, {@link ArActionGroupWander} ...) are meant
 * to be used one at a time, with {@code activateExclusive}. Methods may be called from any thread.
 */
public class ArActionGroup {

  private final ArRobot robot;
  private final Object lock = new Object();

  @GuardedBy("lock")
  private final List<ArAction> actions = new ArrayList<>();

  /** A group whose actions go to {@code robot}. */
  public ArActionGroup(ArRobot robot) {
    this.robot = Objects.requireNonNull(robot, "an action group needs the robot its actions drive");
  }

  /** The robot the group's actions are added to. */
  public ArRobot getRobot() {
    return robot;
  }

  /**
   * Adds {@code action} to the group and to the robot with {@code priority} (as {@link
   * ArRobot#addAction}).
   */
  public void addAction(ArAction action, int priority) {
    Objects.requireNonNull(action, "action");
    synchronized (lock) {
      if (!actions.contains(action)) {
        actions.add(action);
      }
    }
    robot.addAction(action, priority);
  }

  /** Removes {@code action} from the group and from the robot. */
  public void remAction(ArAction action) {
    synchronized (lock) {
      actions.remove(action);
    }
    robot.remAction(action);
  }

  /** Activates every action of the group (the robot's other actions are left as they are). */
  public void activate() {
    for (ArAction a : getActionList()) {
      a.activate();
    }
  }

  /** Deactivates every action of the robot, then activates this group's. */
  public void activateExclusive() {
    robot.deactivateActions();
    activate();
  }

  /** Deactivates every action of the group (the robot's other actions are left as they are). */
  public void deactivate() {
    for (ArAction a : getActionList()) {
      a.deactivate();
    }
  }

  /** The group's actions, in the order they were added (a copy). */
  public List<ArAction> getActionList() {
    synchronized (lock) {
      return List.copyOf(actions);
    }
  }

  /** Removes the group's actions from the robot (they stay in the group and can be re-added). */
  public void removeActions() {
    for (ArAction a : getActionList()) {
      robot.remAction(a);
    }
  }
}
