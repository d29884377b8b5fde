package org.jaria.action;

import java.util.Objects;
import org.jaria.input.ArJoyHandler;

/**
 * Drives the robot with a joystick while its first button is held (ARIA's {@code
 * ArActionJoydrive}). Pushing forward drives forward, up to the maximum translational velocity at
 * full deflection; pushing sideways turns, up to the maximum turn amount (degrees per cycle). With
 * throttle parameters set and a joystick that has a throttle axis, the throttle scales the speed
 * between the low and high values instead.
 *
 * <p>When no button is held it stops the robot, or — with {@code stopIfNoButtonPressed} false —
 * asks for nothing, so lower-priority actions (keyboard driving, say) take over. Without a joystick
 * it asks for nothing.
 *
 * <p>The joystick comes from an {@link ArJoyHandler} fed by the program; ARIA's global joystick is
 * replaced by passing the handler in (or using the one the action makes, {@link #getJoyHandler()}).
 */
public class ArActionJoydrive extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private final ArJoyHandler joyHandler;
  private volatile double transVelMax;
  private volatile double turnAmountMax;
  private volatile boolean stopIfNoButtonPressed;
  private volatile boolean useThrottle;
  private volatile double lowThrottle;
  private volatile double highThrottle;

  /** "joydrive" with ARIA's defaults (400 mm/s, 15°, stop without button) and its own handler. */
  public ArActionJoydrive() {
    this(new ArJoyHandler(), "joydrive", 400, 15, true, true);
  }

  /** ARIA's defaults, reading {@code joyHandler}. */
  public ArActionJoydrive(ArJoyHandler joyHandler) {
    this(joyHandler, "joydrive", 400, 15, true, true);
  }

  /**
   * A joydrive action with its own joystick handler (reach it with {@link #getJoyHandler()}).
   *
   * @param name the action's name
   * @param transVelMax velocity at full forward deflection, mm/s
   * @param turnAmountMax turn at full sideways deflection, degrees per cycle
   * @param stopIfNoButtonPressed stop the robot while no button is held (else ask for nothing)
   * @param useOSCalForJoystick trust the joystick's values as calibrated
   */
  public ArActionJoydrive(
      String name,
      double transVelMax,
      double turnAmountMax,
      boolean stopIfNoButtonPressed,
      boolean useOSCalForJoystick) {
    this(
        new ArJoyHandler(useOSCalForJoystick),
        name,
        transVelMax,
        turnAmountMax,
        stopIfNoButtonPressed,
        useOSCalForJoystick);
  }

  /** A joydrive action reading {@code joyHandler}, with the parameters as above. */
  public ArActionJoydrive(
      ArJoyHandler joyHandler,
      String name,
      double transVelMax,
      double turnAmountMax,
      boolean stopIfNoButtonPressed,
      boolean useOSCalForJoystick) {
    super(
        name,
        "This action reads the joystick and sets the translational and rotational velocities"
            + " based on this.");
    this.joyHandler = Objects.requireNonNull(joyHandler, "joyHandler");
    this.transVelMax = transVelMax;
    this.turnAmountMax = turnAmountMax;
    this.stopIfNoButtonPressed = stopIfNoButtonPressed;
    joyHandler.setUseOSCal(useOSCalForJoystick);
  }

  /** The joystick handler read. */
  public ArJoyHandler getJoyHandler() {
    return joyHandler;
  }

  /** Whether a joystick is connected. */
  public boolean joystickInited() {
    return joyHandler.haveJoystick();
  }

  /** Sets the velocity at full deflection (mm/s) and the maximum turn (degrees per cycle). */
  public void setSpeeds(double transVelMax, double turnAmountMax) {
    this.transVelMax = transVelMax;
    this.turnAmountMax = turnAmountMax;
  }

  /** Whether the robot is stopped while no button is held. */
  public boolean getStopIfNoButtonPressed() {
    return stopIfNoButtonPressed;
  }

  /** Sets whether the robot is stopped while no button is held (else nothing is asked). */
  public void setStopIfNoButtonPressed(boolean stop) {
    stopIfNoButtonPressed = stop;
  }

  /** Whether the joystick's values are trusted as calibrated. */
  public boolean getUseOSCal() {
    return joyHandler.getUseOSCal();
  }

  /** Sets whether the joystick's values are trusted as calibrated. */
  public void setUseOSCal(boolean useOSCal) {
    joyHandler.setUseOSCal(useOSCal);
  }

  /**
   * Uses the throttle axis: full forward deflection then gives a speed between {@code lowSpeed}
   * (throttle back) and {@code highSpeed} (throttle forward), mm/s.
   */
  public void setThrottleParams(double lowSpeed, double highSpeed) {
    lowThrottle = lowSpeed;
    highThrottle = highSpeed;
    useThrottle = true;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    if (!joyHandler.haveJoystick()) {
      return null;
    }
    if (joyHandler.getButton(1)) {
      ArJoyHandler.JoyVec3f d = joyHandler.getDoubles();
      double rot = d.x() * turnAmountMax;
      double trans;
      if (!useThrottle || !joyHandler.haveZAxis()) {
        trans = d.y() * transVelMax;
      } else {
        double throttle = (joyHandler.getAxis(3) + 1.0) / 2.0;
        trans = d.y() * (lowThrottle + throttle * (highThrottle - lowThrottle));
      }
      desired.setVel(trans);
      desired.setDeltaHeading(-rot);
      return desired;
    }
    if (stopIfNoButtonPressed) {
      desired.setVel(0);
      desired.setDeltaHeading(0);
      return desired;
    }
    return null;
  }
}
