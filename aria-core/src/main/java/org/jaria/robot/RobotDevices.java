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
import org.jaria.clock.Clock;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.DropCounters;
import org.jaria.range.ArRangeDevice;

/**
 * What the robot knows about its surroundings and how it decides: range devices, the pose
 * correction that localization applies, and the actions with their resolver. Part of {@link
 * ArRobot}'s API; use it through ArRobot.
 */
public abstract class RobotDevices extends RobotMotion {

  final CopyOnWriteArrayList<ArRangeDevice> rangeDevices = new CopyOnWriteArrayList<>();
  private final CopyOnWriteArrayList<ArResolver.PrioritizedAction> actions =
      new CopyOnWriteArrayList<>();
  private final Object desiredLock = new Object();

  @GuardedBy("desiredLock")
  private final ArActionDesired actionDesired = new ArActionDesired();

  private volatile ArResolver resolver = new ArPriorityResolver();

  RobotDevices(Clock clock, ArRobotParams params, DropCounters drops) {
    super(clock, params, drops);
  }

  // ================================================================ pose transform

  /**
   * Declares that the robot is at {@code pose} now (ARIA's {@code moveTo}): odometry keeps
   * counting, but {@link #getPose()} and everything that uses it jump to the new pose. Range
   * devices' buffers move along.
   */
  public void moveTo(ArPose pose) {
    ArTransform before = processor.getEncoderTransform();
    publish(processor.moveTo(pose));
    shiftRangeDevices(processor.getEncoderTransform().compose(before.inverse()));
  }

  /**
   * Sets the encoder→global transform so that odometry pose {@code encoderPose} corresponds to
   * global pose {@code globalPose} (what a localizer reports for an odometry pose it used).
   */
  public void setEncoderTransform(ArPose encoderPose, ArPose globalPose) {
    ArTransform before = processor.getEncoderTransform();
    publish(processor.setEncoderTransform(encoderPose, globalPose));
    shiftRangeDevices(processor.getEncoderTransform().compose(before.inverse()));
  }

  private void shiftRangeDevices(ArTransform change) {
    for (ArRangeDevice d : rangeDevices) {
      d.applyTransform(change);
    }
  }

  /** The transform from odometry coordinates to global coordinates. */
  public ArTransform getEncoderTransform() {
    return processor.getEncoderTransform();
  }

  /** The transform from the robot's local frame to global coordinates (at the current pose). */
  public ArTransform getToGlobalTransform() {
    return ArTransform.ofPose(getPose());
  }

  /** The transform from global coordinates to the robot's local frame. */
  public ArTransform getToLocalTransform() {
    return getToGlobalTransform().inverse();
  }

  // ================================================================ range devices

  /** Removes a range device. */
  public void remRangeDevice(ArRangeDevice device) {
    rangeDevices.remove(device);
  }

  /** The range device called {@code deviceName}, or null. */
  public ArRangeDevice findRangeDevice(String deviceName) {
    for (ArRangeDevice d : rangeDevices) {
      if (d.getName().equals(deviceName)) {
        return d;
      }
    }
    return null;
  }

  /** The range devices added to this robot. */
  public List<ArRangeDevice> getRangeDeviceList() {
    return List.copyOf(rangeDevices);
  }

  /**
   * The closest current reading of any range device in the sector from {@code startAngle}
   * counter-clockwise to {@code endAngle} (degrees, 0 ahead), in mm from the robot's centre; a
   * value of at least the devices' maximum range means nothing was seen.
   */
  public double checkRangeDevicesCurrentPolar(double startAngle, double endAngle) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.currentReadingPolar(startAngle, endAngle));
    }
    return best;
  }

  /** As {@link #checkRangeDevicesCurrentPolar}, over the cumulative buffers. */
  public double checkRangeDevicesCumulativePolar(double startAngle, double endAngle) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.cumulativeReadingPolar(startAngle, endAngle));
    }
    return best;
  }

  /**
   * The closest current reading of any range device inside the box with corners (x1, y1), (x2, y2)
   * in the robot's frame (x forward, y left, mm); a very large value if none.
   */
  public double checkRangeDevicesCurrentBox(double x1, double y1, double x2, double y2) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.currentReadingBox(x1, y1, x2, y2));
    }
    return best;
  }

  /** As {@link #checkRangeDevicesCurrentBox}, over the cumulative buffers. */
  public double checkRangeDevicesCumulativeBox(double x1, double y1, double x2, double y2) {
    double best = Double.MAX_VALUE;
    for (ArRangeDevice d : rangeDevices) {
      best = Math.min(best, d.cumulativeReadingBox(x1, y1, x2, y2));
    }
    return best;
  }

  /**
   * Sets how each odometry heading change is corrected (ARIA's {@code
   * setEncoderCorrectionCallback}): a gyro replaces the wheels' turn with its own. Null removes the
   * correction. Called on the cycle thread for every SIP.
   */
  public void setEncoderCorrectionCallback(HeadingCorrection correction) {
    processor.setHeadingCorrection(correction);
  }

  // ================================================================ actions

  /** Adds {@code action} to the list (or changes its priority), keeping it sorted. */
  void insertAction(ArAction action, int priority) {
    synchronized (actions) {
      actions.removeIf(p -> p.action() == action);
      List<ArResolver.PrioritizedAction> copy = new ArrayList<>(actions);
      copy.add(new ArResolver.PrioritizedAction(priority, action));
      copy.sort(Comparator.comparingInt(ArResolver.PrioritizedAction::priority).reversed());
      actions.clear();
      actions.addAll(copy);
    }
  }

  /** Removes an action. */
  public boolean remAction(ArAction action) {
    synchronized (actions) {
      return actions.removeIf(p -> p.action() == action);
    }
  }

  /** Removes the first action called {@code name}. */
  public boolean remAction(String name) {
    ArAction a = findAction(name);
    return a != null && remAction(a);
  }

  /** The action called {@code name}, or null. */
  public ArAction findAction(String name) {
    for (ArResolver.PrioritizedAction p : actions) {
      if (p.action().getName().equals(name)) {
        return p.action();
      }
    }
    return null;
  }

  /** The actions with their priorities, highest first. */
  public List<ArResolver.PrioritizedAction> getActionList() {
    return List.copyOf(actions);
  }

  /** Deactivates every action. */
  public void deactivateActions() {
    for (ArResolver.PrioritizedAction p : actions) {
      p.action().deactivate();
    }
  }

  /** Replaces the resolver (the default is an {@link ArPriorityResolver}). */
  public void setResolver(ArResolver r) {
    resolver = r == null ? new ArPriorityResolver() : r;
  }

  /** The resolver. */
  public ArResolver getResolver() {
    return resolver;
  }

  /** The actions' combined desire in the last cycle (a copy). */
  public ArActionDesired getActionDesired() {
    ArActionDesired copy = new ArActionDesired();
    synchronized (desiredLock) {
      copy.copyFrom(actionDesired);
    }
    return copy;
  }

  /** Runs the resolver over the actions (when connected); returns this cycle's desire. */
  ArActionDesired resolveActions(ArRobot robot, boolean connected) {
    synchronized (desiredLock) {
      actionDesired.reset();
      if (connected && !actions.isEmpty()) {
        ArActionDesired d = resolver.resolve(actions, robot);
        if (d != null) {
          actionDesired.merge(d);
        }
      }
      return actionDesired;
    }
  }
}
