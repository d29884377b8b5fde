package org.jaria.action;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import org.jaria.input.ArJoyHandler;
import org.jaria.robot.ArRobot;

/**
 * Joystick input for an {@link ArActionRatioInput} (ARIA's {@code ArRatioInputJoydrive}): while the
 * first button is held, the stick's deflection sets the translation and rotation ratios and the
 * throttle axis (if any) the throttle. When the button is released it sets the ratios to 0 once
 * (every cycle with {@code stopIfNoButtonPressed}), then leaves them to other inputs.
 */
public class ArRatioInputJoydrive {

  private final ArActionRatioInput input;
  private final ArJoyHandler joyHandler;
  private final Runnable fireCb = this::fireCallback;
  private volatile boolean stopIfNoButtonPressed;

  @GuardedBy("this")
  private boolean firedLast;

  /** Joystick input at ARIA's defaults: priority 50, no stop without button, OS calibration. */
  public ArRatioInputJoydrive(ArRobot robot, ArActionRatioInput input, ArJoyHandler joyHandler) {
    this(robot, input, joyHandler, 50, false, true);
  }

  /**
   * Joystick input.
   *
   * @param robot the robot (kept for ARIA's signature)
   * @param input the ratio action to drive
   * @param joyHandler the joystick
   * @param priority the fire-callback priority on {@code input}
   * @param stopIfNoButtonPressed set the ratios to 0 every cycle no button is held
   * @param useOSCalForJoystick trust the joystick's values as calibrated
   */
  public ArRatioInputJoydrive(
      ArRobot robot,
      ArActionRatioInput input,
      ArJoyHandler joyHandler,
      int priority,
      boolean stopIfNoButtonPressed,
      boolean useOSCalForJoystick) {
    this.input = input;
    this.joyHandler = joyHandler;
    this.stopIfNoButtonPressed = stopIfNoButtonPressed;
    joyHandler.setUseOSCal(useOSCalForJoystick);
    input.addFireCallback(priority, fireCb);
  }

  /** Whether a joystick is connected. */
  public boolean joystickInited() {
    return joyHandler.haveJoystick();
  }

  /** Sets whether the ratios are zeroed every cycle no button is held. */
  public void setStopIfNoButtonPressed(boolean stop) {
    stopIfNoButtonPressed = stop;
  }

  /** Whether the ratios are zeroed every cycle no button is held. */
  public boolean getStopIfNoButtonPressed() {
    return stopIfNoButtonPressed;
  }

  private synchronized void fireCallback() {
    if (!joyHandler.haveJoystick()) {
      return;
    }
    if (joyHandler.getButton(1)) {
      ArJoyHandler.JoyVec3f d = joyHandler.getDoubles();
      double throttle = joyHandler.haveZAxis() ? (joyHandler.getAxis(3) + 1.0) / 2.0 : 1;
      input.setRatios(d.y() * 100, -d.x() * 100, throttle * 100);
      firedLast = true;
    } else if (stopIfNoButtonPressed || firedLast) {
      firedLast = false;
      input.setRatios(0, 0, input.getThrottleRatio());
    }
  }
}
