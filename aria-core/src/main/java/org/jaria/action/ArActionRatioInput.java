package org.jaria.action;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;

/**
 * Drives from abstract ratios given by one or more input sources (ARIA's {@code
 * ArActionRatioInput}): a translation ratio from −100 (full speed backwards) to 100 (full speed
 * forwards), a rotation ratio from −100 (full right) to 100 (full left), and a throttle from 0
 * (stopped) to 100 (full). Input sources — keyboard, joystick, a network client — either set the
 * ratios directly or register a fire callback that sets them just before each cycle's desire is
 * computed.
 *
 * <p>The ratios map to speeds through the parameters: full throttle forwards defaults to the
 * robot's maximum translational velocity, backwards to a quarter of it; the rotational velocity at
 * full rotation goes from the "stopped" value (default 50 deg/s) to the "full forwards/backwards"
 * value (default 25 deg/s) as the robot speeds up. Ratios inside the dead zones (10 % translation,
 * 5 % rotation) count as 0. Pulling against the current motion (a ratio beyond 50 the other way)
 * raises the deceleration threefold, at minimum strength so that safety limiters still win.
 *
 * <p>Activating the action resets the ratios to 0. Lateral motion of omnidirectional robots is not
 * modelled.
 */
public class ArActionRatioInput extends ArAction {

  private record FireCallback(int priority, Runnable callback) {}

  private final ArActionDesired desired = new ArActionDesired();
  private final List<FireCallback> fireCallbacks = new ArrayList<>();
  private final CopyOnWriteArrayList<Runnable> activateCallbacks = new CopyOnWriteArrayList<>();
  private final CopyOnWriteArrayList<Runnable> deactivateCallbacks = new CopyOnWriteArrayList<>();
  private double transRatio;
  private double rotRatio;
  private double throttleRatio;
  private double fullThrottleForwards;
  private double fullThrottleBackwards;
  private double rotAtFullForwards = 25;
  private double rotAtFullBackwards = 25;
  private double rotAtStopped = 50;
  private double transDeadZone = 10;
  private double rotDeadZone = 5;

  /** "RatioInput". */
  public ArActionRatioInput() {
    this("RatioInput");
  }

  /** A ratio-input action with a name. */
  public ArActionRatioInput(String name) {
    super(name, "RatioInputs vel and heading");
  }

  /** Sets all three ratios, each pulled into its range. */
  public void setRatios(double transRatio, double rotRatio, double throttleRatio) {
    locked(
        () -> {
          setTransRatio(transRatio);
          setRotRatio(rotRatio);
          setThrottleRatio(throttleRatio);
        });
  }

  /** Sets the translation ratio, −100 (full backwards) to 100 (full forwards). */
  public void setTransRatio(double ratio) {
    locked(() -> transRatio = clamp(ratio, -100, 100));
  }

  /** Sets the rotation ratio, −100 (full right) to 100 (full left). */
  public void setRotRatio(double ratio) {
    locked(() -> rotRatio = clamp(ratio, -100, 100));
  }

  /** Sets the throttle, 0 (stopped) to 100 (full). */
  public void setThrottleRatio(double ratio) {
    locked(() -> throttleRatio = clamp(ratio, 0, 100));
  }

  private static double clamp(double v, double lo, double hi) {
    if (Double.isNaN(v)) {
      return 0;
    }
    return Math.max(lo, Math.min(hi, v));
  }

  /** The translation ratio. */
  public double getTransRatio() {
    return lockedGet(() -> transRatio);
  }

  /** The rotation ratio. */
  public double getRotRatio() {
    return lockedGet(() -> rotRatio);
  }

  /** The throttle. */
  public double getThrottleRatio() {
    return lockedGet(() -> throttleRatio);
  }

  /**
   * Sets how ratios map to speeds; a value below 1 means "from the robot" (see the class comment).
   *
   * @param fullThrottleForwards forward speed at full ratio and throttle, mm/s
   * @param fullThrottleBackwards backward speed at full ratio and throttle, mm/s
   * @param rotAtFullForwards rotational velocity at full rotation when going full forwards, deg/s
   * @param rotAtFullBackwards rotational velocity at full rotation when going full backwards
   * @param rotAtStopped rotational velocity at full rotation when stopped, deg/s
   */
  public void setParameters(
      double fullThrottleForwards,
      double fullThrottleBackwards,
      double rotAtFullForwards,
      double rotAtFullBackwards,
      double rotAtStopped) {
    locked(
        () -> {
          this.fullThrottleForwards = fullThrottleForwards;
          this.fullThrottleBackwards = fullThrottleBackwards;
          this.rotAtFullForwards = rotAtFullForwards;
          this.rotAtFullBackwards = rotAtFullBackwards;
          this.rotAtStopped = rotAtStopped;
        });
  }

  /**
   * Adds a callback run at the start of every fire, to set the ratios. Callbacks run from the
   * lowest priority number to the highest, so higher numbers have the last word.
   */
  public void addFireCallback(int priority, Runnable callback) {
    locked(
        () -> {
          int i = 0;
          while (i < fireCallbacks.size() && fireCallbacks.get(i).priority() <= priority) {
            i++;
          }
          fireCallbacks.add(i, new FireCallback(priority, callback));
        });
  }

  /** Removes a fire callback. */
  public void remFireCallback(Runnable callback) {
    locked(() -> fireCallbacks.removeIf(f -> f.callback() == callback));
  }

  /** Adds a callback run when the action is activated. */
  public void addActivateCallback(Runnable callback, ArListPos position) {
    if (position == ArListPos.FIRST) {
      activateCallbacks.add(0, callback);
    } else {
      activateCallbacks.add(callback);
    }
  }

  /** Removes an activate callback. */
  public void remActivateCallback(Runnable callback) {
    activateCallbacks.remove(callback);
  }

  /** Adds a callback run when the action is deactivated. */
  public void addDeactivateCallback(Runnable callback, ArListPos position) {
    if (position == ArListPos.FIRST) {
      deactivateCallbacks.add(0, callback);
    } else {
      deactivateCallbacks.add(callback);
    }
  }

  /** Removes a deactivate callback. */
  public void remDeactivateCallback(Runnable callback) {
    deactivateCallbacks.remove(callback);
  }

  /**
   * Activates the action; if it was inactive, zeroes the ratios and runs the activate callbacks.
   */
  @Override
  public void activate() {
    if (!isActive()) {
      locked(
          () -> {
            transRatio = 0;
            rotRatio = 0;
            throttleRatio = 0;
          });
      activateCallbacks.forEach(Runnable::run);
    }
    super.activate();
  }

  /**
   * Deactivates the action; if it was active, zeroes the ratios and runs the deactivate callbacks.
   * (ARIA tested for "inactive" here, so its deactivate callbacks never ran.)
   */
  @Override
  public void deactivate() {
    if (isActive()) {
      locked(
          () -> {
            transRatio = 0;
            rotRatio = 0;
            throttleRatio = 0;
          });
      deactivateCallbacks.forEach(Runnable::run);
    }
    super.deactivate();
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    for (FireCallback f : List.copyOf(fireCallbacks)) {
      f.callback().run();
    }
    ArRobot robot = getRobot();
    desired.reset();
    double fullForwards = fullThrottleForwards < 1 ? robot.getTransVelMax() : fullThrottleForwards;
    double fullBackwards =
        fullThrottleBackwards < 1 ? robot.getTransVelMax() / 4 : fullThrottleBackwards;
    double rotFullForwards = rotAtFullForwards < 1 ? robot.getRotVelMax() / 2 : rotAtFullForwards;
    double rotFullBackwards =
        rotAtFullBackwards < 1 ? robot.getRotVelMax() / 2 : rotAtFullBackwards;
    double rotStopped = rotAtStopped < 1 ? robot.getRotVelMax() : rotAtStopped;
    double throttle = throttleRatio / 100.0;
    double speedRatio = fullForwards > 0 ? Math.abs(robot.getVel() / fullForwards) : 0;

    if (transRatio > transDeadZone) {
      desired.setVel(transRatio / 100.0 * fullForwards * throttle);
      desired.setRotVel(rotFor((rotFullForwards - rotStopped) * speedRatio + rotStopped, throttle));
    } else if (transRatio < -transDeadZone) {
      desired.setVel(transRatio / 100.0 * fullBackwards * throttle);
      desired.setRotVel(
          rotFor((rotFullBackwards - rotStopped) * speedRatio + rotStopped, throttle));
    } else {
      desired.setVel(0);
      desired.setRotVel(rotFor(rotStopped, throttle));
    }

    if ((robot.getVel() > 0 && transRatio < -50) || (robot.getVel() < 0 && transRatio > 50)) {
      desired.setTransDecel(robot.getTransDecel() * 3, ArActionDesired.MIN_STRENGTH, true);
    }
    if ((robot.getRotVel() > 0 && rotRatio < -50) || (robot.getRotVel() < 0 && rotRatio > 50)) {
      desired.setRotDecel(robot.getRotDecel() * 3, ArActionDesired.MIN_STRENGTH, true);
    }
    return desired;
  }

  private double rotFor(double fullRot, double throttle) {
    if (Math.abs(rotRatio) < rotDeadZone) {
      return 0;
    }
    return rotRatio / 100.0 * fullRot * throttle;
  }
}
