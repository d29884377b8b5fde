package org.jaria.action;

import java.util.List;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * ARIA's default resolver. Actions are taken in decreasing priority. The desires of actions with
 * the same priority are averaged, each channel weighted by strength; the average is then merged
 * into the result so far, where it can only use the strength that higher priorities left over. A
 * channel whose strength has reached 1.0 is closed: nothing of lower priority changes it. Limit
 * channels (maximum speeds, accelerations) take the most restrictive value instead of a weighted
 * one. Absolute headings become changes of heading from the robot's current heading.
 *
 * <p>Each action is shown the desire combined so far when it fires, so a low-priority action can
 * see what higher ones decided.
 */
public class ArPriorityResolver implements ArResolver {

  private static final Logger log = LoggerFactory.getLogger(ArPriorityResolver.class);

  private final ArActionDesired result = new ArActionDesired();
  private final ArActionDesired level = new ArActionDesired();
  private final ArActionDesired shown = new ArActionDesired();

  @Override
  public ArActionDesired resolve(List<PrioritizedAction> actions, ArRobot robot) {
    result.reset();
    double heading = robot == null ? 0 : robot.getTh();
    int i = 0;
    while (i < actions.size()) {
      int priority = actions.get(i).priority();
      level.reset();
      level.startAverage();
      boolean any = false;
      for (; i < actions.size() && actions.get(i).priority() == priority; i++) {
        ArAction a = actions.get(i).action();
        if (!a.isActive()) {
          continue;
        }
        shown.copyFrom(result);
        ArActionDesired d = fireSafely(a);
        if (d == null) {
          continue;
        }
        d.accountForRobotHeading(heading);
        d.sanityCheck(a.getName());
        level.addAverage(d);
        any = true;
      }
      if (any) {
        level.endAverage();
        result.merge(level);
      }
    }
    return result;
  }

  private ArActionDesired fireSafely(ArAction a) {
    try {
      return a.fire(shown);
    } catch (RuntimeException e) {
      // One action's bug must not stop the others: it is switched off and reported.
      a.deactivate();
      log.error("action '{}' threw and has been deactivated", a.getName(), e);
      return null;
    }
  }
}
