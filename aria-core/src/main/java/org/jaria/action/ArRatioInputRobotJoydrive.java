package org.jaria.action;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import org.jaria.input.ArJoyHandler;
import org.jaria.input.ArRobotJoyHandler;
import org.jaria.robot.ArRobot;

/**
 * Input from the robot's own joystick for an {@link ArActionRatioInput} (ARIA's {@code
 * ArRatioInputRobotJoydrive}). With {@code requireDeadmanPushed} (the default) nothing is set
 * unless the first button is held; then the stick sets the ratios directly. Without it, only
 * deflections beyond a third count, and a centred stick stops the robot once before leaving the
 * ratios to other inputs.
 */
public class ArRatioInputRobotJoydrive {

  private final ArActionRatioInput input;
  private final ArRobotJoyHandler joy;
  private final Runnable fireCb = this::fireCallback;
  private final boolean requireDeadmanPushed;

  @GuardedBy("this")
  private boolean deadZoneLast;

  /** Robot-joystick input at ARIA's defaults: priority 75, deadman required. */
  public ArRatioInputRobotJoydrive(ArRobot robot, ArActionRatioInput input) {
    this(robot, input, 75, true);
  }

  /**
   * Robot-joystick input; makes its own {@link ArRobotJoyHandler} for {@code robot}.
   *
   * @param robot the robot whose joystick is read
   * @param input the ratio action to drive
   * @param priority the fire-callback priority on {@code input}
   * @param requireDeadmanPushed drive only while the first button is held
   */
  public ArRatioInputRobotJoydrive(
      ArRobot robot, ArActionRatioInput input, int priority, boolean requireDeadmanPushed) {
    this.input = input;
    this.joy = new ArRobotJoyHandler(robot);
    this.requireDeadmanPushed = requireDeadmanPushed;
    input.addFireCallback(priority, fireCb);
  }

  /** The robot-joystick reader. */
  public ArRobotJoyHandler getRobotJoyHandler() {
    return joy;
  }

  private synchronized void fireCallback() {
    if (requireDeadmanPushed && !joy.getButton1()) {
      deadZoneLast = false;
      return;
    }
    ArJoyHandler.JoyVec3f d = joy.getDoubles();
    double rotRatio = -d.x() * 100;
    double transRatio = d.y() * 100;
    double throttleRatio = d.z() * 100;
    boolean doTrans = requireDeadmanPushed || Math.abs(transRatio) > 33;
    boolean doRot = requireDeadmanPushed || Math.abs(rotRatio) > 33;
    if (!doTrans && !doRot) {
      if (deadZoneLast) {
        return;
      }
      input.setRatios(0, 0, throttleRatio);
      deadZoneLast = true;
      return;
    }
    deadZoneLast = false;
    input.setRatios(doTrans ? transRatio : 0, doRot ? rotRatio : 0, throttleRatio);
  }
}
