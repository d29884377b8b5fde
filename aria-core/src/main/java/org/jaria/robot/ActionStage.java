package org.jaria.robot;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArPriorityResolver;
import org.jaria.action.ArResolver;

/**
 * The robot's actions, by priority, and the resolver that combines their desires once per cycle.
 * This is the seam between the robot and the actions: the rest of the robot sees only the resolved
 * {@link ArActionDesired}. Actions may be added and removed from any thread; the list is copied on
 * write, so the cycle reads it without a lock.
 */
final class ActionStage {

  private final CopyOnWriteArrayList<ArResolver.PrioritizedAction> actions =
      new CopyOnWriteArrayList<>();
  private final Object desiredLock = new Object();

  @GuardedBy("desiredLock")
  private final ArActionDesired desired = new ArActionDesired();

  private volatile ArResolver resolver = new ArPriorityResolver();

  /** Adds {@code action} to the list (or changes its priority), keeping it sorted. */
  void add(ArAction action, int priority) {
    synchronized (actions) {
      actions.removeIf(p -> p.action() == action);
      List<ArResolver.PrioritizedAction> copy = new ArrayList<>(actions);
      copy.add(new ArResolver.PrioritizedAction(priority, action));
      copy.sort(Comparator.comparingInt(ArResolver.PrioritizedAction::priority).reversed());
      actions.clear();
      actions.addAll(copy);
    }
  }

  boolean remove(ArAction action) {
    synchronized (actions) {
      return actions.removeIf(p -> p.action() == action);
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

  List<ArResolver.PrioritizedAction> list() {
    return List.copyOf(actions);
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
    synchronized (desiredLock) {
      desired.reset();
      if (connected && !actions.isEmpty()) {
        ArActionDesired d = resolver.resolve(actions, robot);
        if (d != null) {
          desired.merge(d);
        }
      }
      return desired;
    }
  }
}
