package org.jaria.arnl;

import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;

/**
 * Stops the robot while localization is lost (ARNL's {@code ArActionLost}): driving on with a wrong
 * pose only makes things worse. When the robot becomes lost while following a path, the goal fails
 * (FAILED_MOVE, "localization lost"). Add it above the path-following action, e.g. {@code
 * pathTask.getPathPlanActionGroup().addAction(new ArActionLost(loc, pathTask), 150)}.
 */
public class ArActionLost extends ArAction {

  private final ArBaseLocalizationTask loc;
  private final ArPathPlanningTask path;
  private final ArActionDesired desired = new ArActionDesired();
  // fire() only, on the robot's cycle thread.
  private boolean wasLost;

  /** Stops the robot while {@code loc} is lost. */
  public ArActionLost(ArBaseLocalizationTask loc) {
    this(loc, null);
  }

  /** Stops the robot while {@code loc} is lost, and fails {@code path}'s goal when it gets lost. */
  public ArActionLost(ArBaseLocalizationTask loc, ArPathPlanningTask path) {
    super("lost", "stops the robot while localization is lost");
    this.loc = loc;
    this.path = path;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    boolean lost = loc.getRobotIsLostFlag();
    if (lost && !wasLost && path != null && path.isActive()) {
      path.trackingFailed(loc.getFailedUpdateCount());
    }
    wasLost = lost;
    if (!lost) {
      return null;
    }
    desired.reset();
    desired.setVel(0);
    desired.setRotVel(0);
    return desired;
  }
}
