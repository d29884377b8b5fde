package org.jaria.action;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keyboard input for an {@link ArActionRatioInput} (ARIA's {@code ArRatioInputKeydrive}): Up and
 * Down change the translation ratio by the velocity increment per press (5 %), Left and Right turn
 * at full rotation for the cycle they are pressed in, Space stops. The keys are taken the first
 * time the ratio action fires (attaching the key handler to the robot with ARIA's default keys if
 * it is not attached yet), and given up while the ratio action is deactivated.
 */
public class ArRatioInputKeydrive {

  private static final Logger log = LoggerFactory.getLogger(ArRatioInputKeydrive.class);
  private static final double THROTTLE = 100;

  private final ArRobot robot;
  private final ArActionRatioInput input;
  private final ArKeyHandler keyHandler;
  private final Runnable upCb = this::up;
  private final Runnable downCb = this::down;
  private final Runnable leftCb = this::left;
  private final Runnable rightCb = this::right;
  private final Runnable spaceCb = this::space;
  private final Runnable fireCb = this::fireCallback;
  private final Runnable activateCb = this::activate;
  private final Runnable deactivateCb = this::deactivate;
  private final double velIncrement;

  @GuardedBy("this")
  private double transRatio;

  @GuardedBy("this")
  private double rotRatio;

  @GuardedBy("this")
  private boolean haveKeys;

  /** Keyboard input at ARIA's defaults: fire-callback priority 25, 5 % per press. */
  public ArRatioInputKeydrive(ArRobot robot, ArActionRatioInput input, ArKeyHandler keyHandler) {
    this(robot, input, keyHandler, 25, 5);
  }

  /**
   * Keyboard input.
   *
   * @param robot the robot (its key handler task is added if needed)
   * @param input the ratio action to drive
   * @param keyHandler the keyboard
   * @param priority the fire-callback priority on {@code input} (higher has the last word)
   * @param velIncrement translation ratio change per Up/Down press, percent
   */
  public ArRatioInputKeydrive(
      ArRobot robot,
      ArActionRatioInput input,
      ArKeyHandler keyHandler,
      int priority,
      double velIncrement) {
    this.robot = robot;
    this.input = input;
    this.keyHandler = keyHandler;
    this.velIncrement = velIncrement;
    input.addFireCallback(priority, fireCb);
    input.addActivateCallback(activateCb, ArListPos.LAST);
    input.addDeactivateCallback(deactivateCb, ArListPos.LAST);
  }

  /** Binds Up, Down, Left, Right and Space. */
  public synchronized void takeKeys() {
    haveKeys = true;
    bind(ArKeyHandler.UP, upCb);
    bind(ArKeyHandler.DOWN, downCb);
    bind(ArKeyHandler.LEFT, leftCb);
    bind(ArKeyHandler.RIGHT, rightCb);
    bind(ArKeyHandler.SPACE, spaceCb);
  }

  private void bind(int key, Runnable cb) {
    if (keyHandler.getKeyHandler(key) != cb && !keyHandler.addKeyHandler(key, cb)) {
      log.warn(
          "The key handler already has a key for {}, keydrive will not work correctly.",
          ArKeyHandler.describe(key));
    }
  }

  /** Unbinds this object's keys. */
  public synchronized void giveUpKeys() {
    haveKeys = false;
    for (Runnable cb : new Runnable[] {upCb, downCb, leftCb, rightCb, spaceCb}) {
      keyHandler.remKeyHandler(cb);
    }
  }

  /** Up: more forward. */
  public synchronized void up() {
    transRatio = Math.min(100, transRatio + velIncrement);
  }

  /** Down: more backward. */
  public synchronized void down() {
    transRatio = Math.max(-100, transRatio - velIncrement);
  }

  /** Left: turn left this cycle. */
  public synchronized void left() {
    rotRatio = 100;
  }

  /** Right: turn right this cycle. */
  public synchronized void right() {
    rotRatio = -100;
  }

  /** Space: stop. */
  public synchronized void space() {
    transRatio = 0;
    rotRatio = 0;
  }

  private synchronized void activate() {
    transRatio = 0;
    rotRatio = 0;
    if (haveKeys) {
      takeKeys();
    }
  }

  private synchronized void deactivate() {
    if (haveKeys) {
      giveUpKeys();
    }
  }

  private synchronized void fireCallback() {
    input.setTransRatio(transRatio);
    input.setRotRatio(rotRatio);
    input.setThrottleRatio(THROTTLE);
    // Turning lasts one cycle: a held key repeats it.
    rotRatio = 0;
    if (!haveKeys) {
      if (keyHandler.getAttachedRobot() == null) {
        keyHandler.attachKeyHandler(robot);
      }
      takeKeys();
    }
  }
}
