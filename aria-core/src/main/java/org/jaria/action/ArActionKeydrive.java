package org.jaria.action;

import java.util.Objects;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Drives the robot with the arrow keys (ARIA's {@code ArActionKeydrive}). Each press of Up or Down
 * changes the desired speed by the velocity increment (up to ± the maximum velocity); each press of
 * Left or Right turns by the turn increment (at most the maximum turn per cycle); Space stops. The
 * speed persists between presses, turning does not.
 *
 * <p>The action takes the keys Up, Down, Left, Right and Space of the {@link ArKeyHandler} it is
 * given when it is added to a robot or activated, and gives them up when deactivated. If the
 * handler is not attached to a robot when the action is added, it is attached with ARIA's default
 * keys (Escape stops the robot's cycle). If a higher-priority action takes the velocity at full
 * strength, the desired speed is reset to what the robot is doing when control returns.
 */
public class ArActionKeydrive extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(ArActionKeydrive.class);

  private final ArActionDesired desired = new ArActionDesired();
  private final ArKeyHandler keyHandler;
  private final Runnable upCb = this::up;
  private final Runnable downCb = this::down;
  private final Runnable leftCb = this::left;
  private final Runnable rightCb = this::right;
  private final Runnable spaceCb = this::space;
  private double transVelMax;
  private double turnAmountMax;
  private double velIncrement;
  private double turnIncrement;
  private double desiredSpeed;
  private double deltaVel;
  private double turnAmount;
  private boolean speedReset = true;
  private volatile boolean haveKeys;

  /** "keydrive" with ARIA's defaults: 400 mm/s, 24° per cycle, 25 mm/s and 8° per press. */
  public ArActionKeydrive(ArKeyHandler keyHandler) {
    this(keyHandler, "keydrive", 400, 24, 25, 8);
  }

  /**
   * A keydrive action.
   *
   * @param keyHandler the keyboard to read
   * @param name the action's name
   * @param transVelMax the fastest it drives, mm/s
   * @param turnAmountMax the most it turns, degrees per cycle
   * @param velIncrement speed change per Up/Down press, mm/s
   * @param turnIncrement turn per Left/Right press, degrees
   */
  public ArActionKeydrive(
      ArKeyHandler keyHandler,
      String name,
      double transVelMax,
      double turnAmountMax,
      double velIncrement,
      double turnIncrement) {
    super(
        name,
        "This action reads the keyboard arrow keys and sets the translational and rotational"
            + " velocities based on this.");
    this.keyHandler = Objects.requireNonNull(keyHandler, "keyHandler");
    this.transVelMax = transVelMax;
    this.turnAmountMax = turnAmountMax;
    this.velIncrement = velIncrement;
    this.turnIncrement = turnIncrement;
  }

  /** The keyboard read. */
  public ArKeyHandler getKeyHandler() {
    return keyHandler;
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    if (keyHandler.getAttachedRobot() == null) {
      keyHandler.attachKeyHandler(r);
    }
    if (isActive()) {
      takeKeys();
    }
  }

  /** Binds Up, Down, Left, Right and Space to this action (logging any already taken). */
  public void takeKeys() {
    locked(
        () -> {
          bind(ArKeyHandler.UP, upCb, "up");
          bind(ArKeyHandler.DOWN, downCb, "down");
          bind(ArKeyHandler.LEFT, leftCb, "left");
          bind(ArKeyHandler.RIGHT, rightCb, "right");
          bind(ArKeyHandler.SPACE, spaceCb, "space");
          haveKeys = true;
        });
  }

  private void bind(int key, Runnable cb, String what) {
    if (keyHandler.getKeyHandler(key) == cb) {
      return;
    }
    if (!keyHandler.addKeyHandler(key, cb)) {
      log.warn("The key handler already has a key for {}, keydrive will not work correctly.", what);
    }
  }

  /** Unbinds this action's keys. */
  public void giveUpKeys() {
    locked(
        () -> {
          for (Runnable cb : new Runnable[] {upCb, downCb, leftCb, rightCb, spaceCb}) {
            keyHandler.remKeyHandler(cb);
          }
          haveKeys = false;
        });
  }

  @Override
  public void activate() {
    if (!isActive() || !haveKeys) {
      takeKeys();
    }
    super.activate();
  }

  @Override
  public void deactivate() {
    if (isActive()) {
      giveUpKeys();
    }
    super.deactivate();
    locked(
        () -> {
          desiredSpeed = 0;
          turnAmount = 0;
        });
  }

  /** Sets the fastest speed (mm/s) and the largest turn (degrees per cycle). */
  public void setSpeeds(double transVelMax, double turnAmountMax) {
    locked(
        () -> {
          this.transVelMax = transVelMax;
          this.turnAmountMax = turnAmountMax;
        });
  }

  /** Sets the speed change (mm/s) and turn (degrees) per key press. */
  public void setIncrements(double velIncrement, double turnIncrement) {
    locked(
        () -> {
          this.velIncrement = velIncrement;
          this.turnIncrement = turnIncrement;
        });
  }

  /** What the Up key does: faster (or less fast backwards). */
  public void up() {
    locked(() -> deltaVel += velIncrement);
  }

  /** What the Down key does: slower (or faster backwards). */
  public void down() {
    locked(() -> deltaVel -= velIncrement);
  }

  /** What the Left key does: turn left. */
  public void left() {
    locked(() -> turnAmount = Math.min(turnAmount + turnIncrement, turnAmountMax));
  }

  /** What the Right key does: turn right. */
  public void right() {
    locked(() -> turnAmount = Math.max(turnAmount - turnIncrement, -turnAmountMax));
  }

  /** What Space does: stop. */
  public void space() {
    locked(
        () -> {
          speedReset = false;
          desiredSpeed = 0;
          turnAmount = 0;
        });
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    desired.reset();
    if (Math.abs(currentDesired.getVelStrength() - 1.0) < 1e-13) {
      speedReset = true;
    }
    if (speedReset && desiredSpeed > 0 && desiredSpeed > robot.getVel()) {
      desiredSpeed = robot.getVel();
    }
    if (speedReset && desiredSpeed < 0 && desiredSpeed < robot.getVel()) {
      desiredSpeed = robot.getVel();
    }
    speedReset = false;
    if (currentDesired.getMaxVelStrength() > 0 && desiredSpeed > currentDesired.getMaxVel()) {
      desiredSpeed = currentDesired.getMaxVel();
    }
    if (currentDesired.getMaxNegVelStrength() > 0 && desiredSpeed < currentDesired.getMaxNegVel()) {
      desiredSpeed = currentDesired.getMaxNegVel();
    }
    desiredSpeed = Math.max(-transVelMax, Math.min(transVelMax, desiredSpeed + deltaVel));
    desired.setVel(desiredSpeed);
    deltaVel = 0;
    desired.setDeltaHeading(turnAmount);
    turnAmount = 0;
    return desired;
  }
}
