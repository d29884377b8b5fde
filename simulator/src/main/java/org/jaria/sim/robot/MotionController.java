package org.jaria.sim.robot;

import org.jaria.geom.ArMath;

/**
 * The ARCOS drive servers: independent translational and rotational setpoints, each either a
 * velocity or a position (MOVE distance, HEAD heading), reached with trapezoidal profiles limited
 * by the session's maximum speeds and (de)accelerations. Every new command abandons the old
 * setpoint of its axis, as on the real controller; the profile is recomputed every tick.
 *
 * <p>Positions are measured the way the robot measures them, by odometry: MOVE counts the distance
 * the encoders report, HEAD aims at a heading of the robot's internal (odometry) frame.
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class MotionController {

  /** Largest forward MOVE, mm. */
  public static final int MOVE_MAX = 5000;

  /** Largest backward MOVE, mm. */
  public static final int MOVE_MIN = -4999;

  private enum TransMode {
    VELOCITY,
    POSITION
  }

  private enum RotMode {
    VELOCITY,
    HEADING
  }

  /**
   * MobileSim's session settings, the same for every model (what its CONFIGpac reports until the
   * client changes them): mm/s, deg/s, mm/s², deg/s².
   */
  public static final int MOBILESIM_TRANS_VEL_MAX = 3000;

  /** MobileSim's default maximum rotational speed, deg/s. */
  public static final int MOBILESIM_ROT_VEL_MAX = 150;

  /** MobileSim's default translational acceleration and deceleration, mm/s². */
  public static final int MOBILESIM_TRANS_ACCEL = 300;

  /** MobileSim's default rotational acceleration and deceleration, deg/s². */
  public static final int MOBILESIM_ROT_ACCEL = 100;

  private final RobotModel model;

  /**
   * MobileSim's way: session defaults from MobileSim rather than the model's FLASH values, and SETV
   * / SETRV taken as sent (MobileSim's robot is limited by its model's top speed alone).
   */
  private final boolean mobileSim;

  private double transVelMax;
  private double rotVelMaxPos;
  private double rotVelMaxNeg;
  private double transAccel;
  private double transDecel;
  private double rotAccel;
  private double rotDecel;

  private double vel;
  private double rotVel;
  private TransMode transMode = TransMode.VELOCITY;
  private double velTarget;
  private double moveRemaining;
  private RotMode rotMode = RotMode.VELOCITY;
  private double rotVelTarget;
  private double headingTarget;
  private boolean eStop;
  private boolean motorsEnabled;
  private boolean held;

  private double lastDs;
  private double lastDth;

  /** A controller with the model's default limits, motors disabled and stopped. */
  public MotionController(RobotModel model) {
    this(model, SimProfile.PIONEER);
  }

  /**
   * A controller with the defaults of {@code profile} (the model's FLASH values, or MobileSim's),
   * motors disabled and stopped.
   */
  public MotionController(RobotModel model, SimProfile profile) {
    this.model = model;
    this.mobileSim = profile == SimProfile.MOBILESIM;
    resetSettings();
  }

  /**
   * Returns every limit to the defaults (the model's FLASH, or MobileSim's), as a new session does.
   */
  public void resetSettings() {
    if (mobileSim) {
      transVelMax = MOBILESIM_TRANS_VEL_MAX;
      rotVelMaxPos = MOBILESIM_ROT_VEL_MAX;
      rotVelMaxNeg = MOBILESIM_ROT_VEL_MAX;
      transAccel = MOBILESIM_TRANS_ACCEL;
      transDecel = MOBILESIM_TRANS_ACCEL;
      rotAccel = MOBILESIM_ROT_ACCEL;
      rotDecel = MOBILESIM_ROT_ACCEL;
      return;
    }
    transVelMax = model.getTransVelMax();
    rotVelMaxPos = model.getRotVelMax();
    rotVelMaxNeg = model.getRotVelMax();
    transAccel = model.getTransAccel();
    transDecel = model.getTransDecel();
    rotAccel = model.getRotAccel();
    rotDecel = model.getRotDecel();
  }

  /** Stops dead (no deceleration) and forgets every setpoint: session start or end. */
  public void halt() {
    vel = 0;
    rotVel = 0;
    transMode = TransMode.VELOCITY;
    velTarget = 0;
    rotMode = RotMode.VELOCITY;
    rotVelTarget = 0;
    moveRemaining = 0;
    eStop = false;
    held = false;
  }

  // ---------------------------------------------------------------- commands

  /** ENABLE: motors on or off. Either way the setpoints are cleared. */
  public void enableMotors(boolean on) {
    motorsEnabled = on;
    halt();
  }

  /** Whether the motors are enabled. */
  public boolean areMotorsEnabled() {
    return motorsEnabled;
  }

  /** Whether an E_STOP deceleration is still in progress (motion commands are ignored). */
  public boolean isEStopping() {
    return eStop;
  }

  /** VEL: translational velocity, mm/s, limited by SETV. */
  public void setVel(double v) {
    if (eStop) {
      return;
    }
    transMode = TransMode.VELOCITY;
    double max = Math.min(transVelMax, model.getTransVelTop());
    velTarget = ArMath.clamp(v, -max, max);
  }

  /** MOVE: travel {@code mm} (+5000 / −4999 at most) at the SETV speed. */
  public void move(double mm) {
    if (eStop) {
      return;
    }
    transMode = TransMode.POSITION;
    moveRemaining = ArMath.clamp(mm, MOVE_MIN, MOVE_MAX);
  }

  /** RVEL / ROTATE: rotational velocity, deg/s (+ counter-clockwise), limited by SETRV(DIR). */
  public void setRotVel(double w) {
    if (eStop) {
      return;
    }
    rotMode = RotMode.VELOCITY;
    double top = model.getRotVelTop();
    rotVelTarget = ArMath.clamp(w, -Math.min(rotVelMaxNeg, top), Math.min(rotVelMaxPos, top));
  }

  /** HEAD: turn the shortest way to the absolute odometry heading {@code deg}. */
  public void setHeading(double deg) {
    if (eStop) {
      return;
    }
    rotMode = RotMode.HEADING;
    headingTarget = ArMath.fixAngle(deg);
  }

  /** DHEAD: turn by {@code deg} from the current heading {@code currentDeg}. */
  public void deltaHeading(double deg, double currentDeg) {
    setHeading(currentDeg + deg);
  }

  /** DCHEAD: turn by {@code deg} from the last heading setpoint (or the current heading). */
  public void deltaControlHeading(double deg, double currentDeg) {
    setHeading((rotMode == RotMode.HEADING ? headingTarget : currentDeg) + deg);
  }

  /**
   * VEL2: wheel velocities, mm/s, decomposed into a translational and a rotational velocity (each
   * then limited as for VEL and RVEL).
   */
  public void setVel2(double left, double right) {
    if (eStop) {
      return;
    }
    setVel((left + right) / 2);
    setRotVel(Math.toDegrees((right - left) / model.getTrackWidth()));
  }

  /** STOP: both axes decelerate to zero; motors stay enabled. */
  public void stop() {
    if (eStop) {
      return;
    }
    setVel(0);
    setRotVel(0);
  }

  /** E_STOP: both axes stop with the maximum deceleration and stay stopped until commanded. */
  public void eStop() {
    transMode = TransMode.VELOCITY;
    velTarget = 0;
    rotMode = RotMode.VELOCITY;
    rotVelTarget = 0;
    eStop = vel != 0 || rotVel != 0;
  }

  /** SETV: maximum translational speed, limited by the firmware top (MobileSim: as sent). */
  public void setTransVelMax(double v) {
    transVelMax = ArMath.clamp(Math.abs(v), 0, mobileSim ? 65535 : model.getTransVelTop());
  }

  /** SETRV: maximum rotational speed both ways (MobileSim: as sent). */
  public void setRotVelMax(double w) {
    double m = ArMath.clamp(Math.abs(w), 0, mobileSim ? 65535 : model.getRotVelTop());
    rotVelMaxPos = m;
    rotVelMaxNeg = m;
  }

  /**
   * SETRVDIR: maximum rotational speed counter-clockwise ({@code w > 0}) or clockwise ({@code w <
   * 0}).
   */
  public void setRotVelMaxDir(double w) {
    double m = ArMath.clamp(Math.abs(w), 0, model.getRotVelTop());
    if (w >= 0) {
      rotVelMaxPos = m;
    } else {
      rotVelMaxNeg = m;
    }
  }

  /**
   * SETA: acceleration ({@code a > 0}) or deceleration ({@code a < 0}), mm/s², limited by the top.
   */
  public void setTransAccel(double a) {
    double m = ArMath.clamp(Math.abs(a), 0, model.getTransAccTop());
    if (a > 0) {
      transAccel = m;
    } else if (a < 0) {
      transDecel = m;
    }
  }

  /** SETRA: rotational acceleration ({@code a > 0}) or deceleration ({@code a < 0}), deg/s². */
  public void setRotAccel(double a) {
    double m = ArMath.clamp(Math.abs(a), 0, model.getRotAccTop());
    if (a > 0) {
      rotAccel = m;
    } else if (a < 0) {
      rotDecel = m;
    }
  }

  /** Watchdog: while held, both axes decelerate to zero; releasing resumes the setpoints. */
  public void setHeld(boolean h) {
    held = h;
  }

  /** Whether the watchdog holds the robot. */
  public boolean isHeld() {
    return held;
  }

  // ---------------------------------------------------------------- profile

  /**
   * Advances the profiles by {@code dt} seconds. Afterwards {@link #lastDistance()} and {@link
   * #lastRotation()} tell how far the wheels want to move in this tick.
   *
   * @param headingDeg the current odometry heading (for HEAD)
   */
  public void update(double dt, double headingDeg) {
    if (!motorsEnabled) {
      vel = 0;
      rotVel = 0;
      lastDs = 0;
      lastDth = 0;
      return;
    }
    double ta = eStop ? model.getTransAccTop() : transAccel;
    double td = eStop ? model.getTransAccTop() : transDecel;
    double ra = eStop ? model.getRotAccTop() : rotAccel;
    double rd = eStop ? model.getRotAccTop() : rotDecel;
    boolean stopping = held || eStop;

    double v0 = vel;
    if (transMode == TransMode.VELOCITY) {
      vel = approach(vel, stopping ? 0 : velTarget, ta, td, dt);
      lastDs = (v0 + vel) / 2 * dt;
    } else {
      double r = moveRemaining;
      double want = stopping ? 0 : Math.signum(r) * moveSpeed(Math.abs(r), td);
      vel = approach(vel, want, ta, td, dt);
      lastDs = (v0 + vel) / 2 * dt;
      if (Math.abs(r) < 1e-6 || (r > 0 ? lastDs >= r : lastDs <= r)) {
        lastDs = r;
        vel = 0;
        transMode = TransMode.VELOCITY;
        velTarget = 0;
        moveRemaining = 0;
      }
    }

    double w0 = rotVel;
    if (rotMode == RotMode.VELOCITY) {
      rotVel = approach(rotVel, stopping ? 0 : rotVelTarget, ra, rd, dt);
      lastDth = (w0 + rotVel) / 2 * dt;
    } else {
      double err = ArMath.subAngle(headingTarget, headingDeg);
      double max = Math.min(err >= 0 ? rotVelMaxPos : rotVelMaxNeg, model.getRotVelTop());
      double want = stopping ? 0 : Math.signum(err) * headSpeed(Math.abs(err), max, rd);
      rotVel = approach(rotVel, want, ra, rd, dt);
      lastDth = (w0 + rotVel) / 2 * dt;
      if (Math.abs(err) < 1e-6 || (err > 0 ? lastDth >= err : lastDth <= err)) {
        // Arrived: hold the heading (the setpoint stays active, as on ARCOS).
        lastDth = err;
        rotVel = 0;
      }
    }
    if (eStop && vel == 0 && rotVel == 0) {
      eStop = false;
    }
  }

  /**
   * How fast MOVE drives with {@code remaining} mm to go: ARCOS's trapezoid (as fast as it can
   * still stop at the goal with deceleration {@code decel}), or MobileSim's proportional control
   * (the distance to go in metres times the SETV speed, per second).
   */
  private double moveSpeed(double remaining, double decel) {
    double max = Math.min(transVelMax, model.getTransVelTop());
    if (mobileSim) {
      return Math.min(model.getTransVelTop(), remaining / 1000 * transVelMax);
    }
    return Math.min(max, Math.sqrt(2 * decel * remaining));
  }

  /**
   * How fast HEAD turns with {@code error} degrees to go: ARCOS's trapezoid, or MobileSim's
   * proportional control (the error in radians as radians per second, at least 0.007 rad/s, at most
   * the SETRV speed), which turns slowly as it nears the heading: ARIA's actions, which send a HEAD
   * a little ahead of the robot every cycle, turn a MobileSim robot much more gently.
   */
  private double headSpeed(double error, double max, double decel) {
    if (mobileSim) {
      return Math.min(max, Math.max(MOBILESIM_HEAD_MIN_SPEED, error));
    }
    return Math.min(max, Math.sqrt(2 * decel * error));
  }

  /** MobileSim's slowest turn towards a HEAD heading, deg/s (0.007 rad/s). */
  static final double MOBILESIM_HEAD_MIN_SPEED = Math.toDegrees(0.007);

  /** Moves {@code cur} towards {@code target} by at most one tick of (de)acceleration. */
  static double approach(double cur, double target, double acc, double dec, double dt) {
    if (cur == target) {
      return cur;
    }
    boolean speedingUp = (target > cur && cur >= 0) || (target < cur && cur <= 0);
    double step = (speedingUp ? acc : dec) * dt;
    return target > cur ? Math.min(target, cur + step) : Math.max(target, cur - step);
  }

  /**
   * A bump ring is being pressed: its spring and the motors' current limit slow the robot at the
   * top deceleration for this tick, while the setpoint stays (the program decides what to do).
   */
  public void cushioned(double dt) {
    double d = model.getTransAccTop() * dt;
    vel = vel > 0 ? Math.max(0, vel - d) : Math.min(0, vel + d);
  }

  /** Whether the motors are driving towards a speed the robot is not making (pushing). */
  public boolean isPushing() {
    boolean wants =
        transMode == TransMode.VELOCITY ? Math.abs(velTarget) > 1 : Math.abs(moveRemaining) > 1;
    return motorsEnabled && !held && !eStop && wants && Math.abs(vel) < 5;
  }

  /** The wheels could not move: the translational (and maybe rotational) speed drops to zero. */
  public void blocked(boolean translation, boolean rotation) {
    if (translation) {
      vel = 0;
    }
    if (rotation) {
      rotVel = 0;
    }
  }

  /** Tells the MOVE server how far the encoders say the robot went this tick, mm. */
  public void measured(double ds) {
    if (transMode == TransMode.POSITION) {
      moveRemaining -= ds;
    }
  }

  /** Distance the wheels want to move this tick, mm. */
  public double lastDistance() {
    return lastDs;
  }

  /** Rotation the wheels want to make this tick, degrees. */
  public double lastRotation() {
    return lastDth;
  }

  /** Current translational velocity, mm/s. */
  public double getVel() {
    return vel;
  }

  /** Current rotational velocity, deg/s. */
  public double getRotVel() {
    return rotVel;
  }

  /** The heading setpoint if HEAD is active, else {@code currentDeg} (for the SIP CONTROL). */
  public double getControlHeading(double currentDeg) {
    return rotMode == RotMode.HEADING ? headingTarget : currentDeg;
  }

  /** Whether a MOVE is still under way. */
  public boolean isMoving() {
    return transMode == TransMode.POSITION;
  }

  /** Current maximum translational speed (SETV), mm/s. */
  public double getTransVelMax() {
    return transVelMax;
  }

  /** Current maximum rotational speed counter-clockwise, deg/s. */
  public double getRotVelMax() {
    return rotVelMaxPos;
  }

  /** Current maximum rotational speed clockwise, deg/s. */
  public double getRotVelMaxNeg() {
    return rotVelMaxNeg;
  }

  /** Current translational acceleration, mm/s². */
  public double getTransAccel() {
    return transAccel;
  }

  /** Current translational deceleration, mm/s². */
  public double getTransDecel() {
    return transDecel;
  }

  /** Current rotational acceleration, deg/s². */
  public double getRotAccel() {
    return rotAccel;
  }

  /** Current rotational deceleration, deg/s². */
  public double getRotDecel() {
    return rotDecel;
  }
}
