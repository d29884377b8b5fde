package org.jaria.robot;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArPriorityResolver;
import org.jaria.action.ArResolver;

/**
 * The robot's actions, by priority, and the resolver that combines their desires once per cycle.
 * This is the seam between the robot and the actions: the rest of the robot sees only the resolved
 * {@link ArActionDesired}.
 *
 * <p>Actions may be added and removed from any thread. Each change builds a new immutable list and
 * publishes it at once, so a cycle reads one complete list, before or after the change, and never
 * one half made; the resolver is handed that list, which stays as it was for the whole cycle.
 */
final class ActionStage {

  private static final Comparator<ArResolver.PrioritizedAction> HIGHEST_FIRST =
      Comparator.comparingInt(ArResolver.PrioritizedAction::priority).reversed();

  /** Makes changes one at a time; readers do not take it. */
  private final Object changing = new Object();

  /** The actions, highest priority first: an immutable list, replaced whole on every change. */
  private volatile List<ArResolver.PrioritizedAction> actions = List.of();

  private final Object desiredLock = new Object();

  @GuardedBy("desiredLock")
  private final ArActionDesired desired = new ArActionDesired();

  private volatile ArResolver resolver = new ArPriorityResolver();

  /**
   * Adds {@code action} to the list (or changes its priority), keeping it sorted; for equal
   * priorities in the order they were added.
   */
  void add(ArAction action, int priority) {
    synchronized (changing) {
      List<ArResolver.PrioritizedAction> next = new ArrayList<>(actions.size() + 1);
      for (ArResolver.PrioritizedAction p : actions) {
        if (p.action() != action) {
          next.add(p);
        }
      }
      next.add(new ArResolver.PrioritizedAction(priority, action));
      next.sort(HIGHEST_FIRST);
      actions = List.copyOf(next);
    }
  }

  boolean remove(ArAction action) {
    synchronized (changing) {
      List<ArResolver.PrioritizedAction> now = actions;
      List<ArResolver.PrioritizedAction> next = new ArrayList<>(now.size());
      for (ArResolver.PrioritizedAction p : now) {
        if (p.action() != action) {
          next.add(p);
        }
      }
      if (next.size() == now.size()) {
        return false;
      }
      actions = List.copyOf(next);
      return true;
    }
  }

  ArAction find(String name) {
    for (ArResolver.PrioritizedAction p : actions) {
      if (p.action().getName().equals(name)) {
        return p.action();
      }
    }
    return null;
  }

  /** The actions as the next cycle will see them: an immutable list, highest priority first. */
  List<ArResolver.PrioritizedAction> list() {
    return actions;
  }

  void deactivateAll() {
    for (ArResolver.PrioritizedAction p : actions) {
      p.action().deactivate();
    }
  }

  void setResolver(ArResolver r) {
    resolver = r == null ? new ArPriorityResolver() : r;
  }

  ArResolver resolver() {
    return resolver;
  }

  /** A copy of the last cycle's combined desire. */
  ArActionDesired desiredCopy() {
    ArActionDesired copy = new ArActionDesired();
    synchronized (desiredLock) {
      copy.copyFrom(desired);
    }
    return copy;
  }

  /** Runs the resolver over the actions (when connected); returns this cycle's desire. */
  ArActionDesired resolve(ArRobot robot, boolean connected) {
    List<ArResolver.PrioritizedAction> now = actions; // one read: the whole cycle sees this list
    synchronized (desiredLock) {
      desired.reset();
      if (connected && !now.isEmpty()) {
        ArActionDesired d = resolver.resolve(now, robot);
        if (d != null) {
          desired.merge(d);
        }
      }
      return desired;
    }
  }
}
