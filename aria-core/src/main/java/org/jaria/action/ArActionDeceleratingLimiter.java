package org.jaria.action;

import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Stops the robot before it hits something by raising the deceleration as needed (ARIA's {@code
 * ArActionDeceleratingLimiter}). Unlike {@link ArActionLimiterForwards}, which caps the speed by
 * distance, this action works out how hard the robot must brake to stop short of the closest
 * reading ahead (or behind, for a backwards limiter), keeping a clearance and a padding that grow
 * with speed, and sets the deceleration and a zero maximum velocity only when braking is needed.
 * Because it touches those channels strongly and others weakly, it can sit low in the priority
 * list.
 *
 * <p>The checked box is as wide as the robot plus the side clearance on each side (interpolated
 * between the slow-speed and fast-speed values) and reaches far ahead. If something is inside the
 * clearance itself while moving, it brakes as hard as allowed (the maximum emergency deceleration,
 * else the robot's top acceleration from its CONFIGpac, else the preferred deceleration) and, with
 * {@code useEStop}, sends an emergency stop.
 *
 * <p>Lateral limiting for omnidirectional robots is not modelled.
 */
public class ArActionDeceleratingLimiter extends ArAction {

  /** Which way of motion the action limits. */
  public enum LimiterType {
    /** Limits driving forwards. */
    FORWARDS,
    /** Limits driving backwards. */
    BACKWARDS
  }

  private static final Logger log = LoggerFactory.getLogger(ArActionDeceleratingLimiter.class);
  private static final double LOOK_AHEAD = 16000;

  private final ArActionDesired desired = new ArActionDesired();
  private volatile LimiterType type;
  private double clearance;
  private double sideClearanceAtSlowSpeed;
  private double paddingAtSlowSpeed;
  private double slowSpeed;
  private double sideClearanceAtFastSpeed;
  private double paddingAtFastSpeed;
  private double fastSpeed;
  private double preferredDecel;
  private boolean useEStop;
  private double maxEmergencyDecel;
  private volatile boolean stopRotationToo;
  private boolean lastStopped;

  /** "limitAndDecel", limiting forwards, with ARIA's default parameters. */
  public ArActionDeceleratingLimiter() {
    this("limitAndDecel", LimiterType.FORWARDS);
  }

  /** A limiter for forwards ({@code true}) or backwards motion, as ARIA's older constructor. */
  public ArActionDeceleratingLimiter(String name, boolean forwards) {
    this(name, forwards ? LimiterType.FORWARDS : LimiterType.BACKWARDS);
  }

  /** A limiter of the given type with ARIA's default parameters ({@link #setParameters()}). */
  public ArActionDeceleratingLimiter(String name, LimiterType type) {
    super(
        name,
        "Slows the robot down and cranks up deceleration so as not to hit anything in front of it.");
    this.type = type;
    setParameters();
  }

  /**
   * Sets ARIA's default parameters: clearance 100 mm, side clearance 50 mm and padding 50 mm at 200
   * mm/s or slower, 400 mm and 300 mm at 1000 mm/s or faster, preferred deceleration 600 mm/s², no
   * e-stop, maximum emergency deceleration from the robot.
   */
  public void setParameters() {
    setParameters(100, 50, 50, 200, 400, 300, 1000, 600, false, 0);
  }

  /**
   * Sets the parameters.
   *
   * @param clearance distance at which to stop, mm
   * @param sideClearanceAtSlowSpeed side distance to keep at slow speed or slower, mm
   * @param paddingAtSlowSpeed distance beyond the clearance to stop at, at slow speed, mm
   * @param slowSpeed speed considered slow, mm/s
   * @param sideClearanceAtFastSpeed side distance to keep at fast speed or faster, mm
   * @param paddingAtFastSpeed distance beyond the clearance to stop at, at fast speed, mm
   * @param fastSpeed speed considered fast, mm/s
   * @param preferredDecel deceleration used unless more is needed, mm/s²
   * @param useEStop send an emergency stop if something is inside the clearance
   * @param maxEmergencyDecel hardest deceleration ever asked for, mm/s² (0: the robot's top)
   */
  public void setParameters(
      double clearance,
      double sideClearanceAtSlowSpeed,
      double paddingAtSlowSpeed,
      double slowSpeed,
      double sideClearanceAtFastSpeed,
      double paddingAtFastSpeed,
      double fastSpeed,
      double preferredDecel,
      boolean useEStop,
      double maxEmergencyDecel) {
    locked(
        () -> {
          this.clearance = clearance;
          this.sideClearanceAtSlowSpeed = sideClearanceAtSlowSpeed;
          this.paddingAtSlowSpeed = paddingAtSlowSpeed;
          this.slowSpeed = slowSpeed;
          this.sideClearanceAtFastSpeed = sideClearanceAtFastSpeed;
          this.paddingAtFastSpeed = paddingAtFastSpeed;
          this.fastSpeed = fastSpeed;
          this.preferredDecel = preferredDecel;
          this.useEStop = useEStop;
          this.maxEmergencyDecel = maxEmergencyDecel;
        });
  }

  /** Whether the action limits forward motion. */
  public boolean getForwards() {
    return type == LimiterType.FORWARDS;
  }

  /** Sets whether the action limits forward (true) or backward motion. */
  public void setForwards(boolean forwards) {
    type = forwards ? LimiterType.FORWARDS : LimiterType.BACKWARDS;
  }

  /** The kind of motion limited. */
  public LimiterType getType() {
    return type;
  }

  /** Whether the rotation is stopped too when something is inside the clearance. */
  public boolean getStopRotationToo() {
    return stopRotationToo;
  }

  /** Sets whether the rotation is stopped too when something is inside the clearance. */
  public void setStopRotationToo(boolean stop) {
    stopRotationToo = stop;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    boolean forwards = type == LimiterType.FORWARDS;
    desired.reset();
    double vel = robot.getVel();
    if ((forwards && vel < -100) || (!forwards && vel > 100)) {
      return null;
    }
    double absVel = Math.abs(vel);
    double sideClearance;
    double padding;
    if (absVel <= slowSpeed) {
      sideClearance = sideClearanceAtSlowSpeed;
      padding = paddingAtSlowSpeed;
    } else if (absVel >= fastSpeed) {
      sideClearance = sideClearanceAtFastSpeed;
      padding = paddingAtFastSpeed;
    } else {
      double f = (absVel - slowSpeed) / (fastSpeed - slowSpeed);
      sideClearance =
          (sideClearanceAtFastSpeed - sideClearanceAtSlowSpeed) * f + sideClearanceAtSlowSpeed;
      padding = (paddingAtFastSpeed - paddingAtSlowSpeed) * f + paddingAtSlowSpeed;
    }

    double halfLength = robot.getRobotLength() / 2.0;
    double halfWidth = robot.getRobotWidth() / 2.0;
    double sign = forwards ? 1 : -1;
    double dist =
        RobotSensing.boxDistance(
            robot,
            0,
            -(halfWidth + sideClearance),
            sign * (halfLength + clearance + padding + LOOK_AHEAD),
            halfWidth + sideClearance);
    double distInner =
        RobotSensing.boxDistance(
            robot,
            0,
            -(halfWidth + sideClearanceAtSlowSpeed),
            sign * (halfLength + clearance + LOOK_AHEAD),
            halfWidth + sideClearanceAtSlowSpeed);
    dist -= halfLength + clearance + padding;
    // What we would e-stop for: no padding.
    distInner -= halfLength + clearance;

    if (distInner < 1 && absVel > 5) {
      if (absVel > 100) {
        if (useEStop) {
          log.info("{}: estopping because of a reading inside the clearance", getName());
          robot.com(ArCommands.E_STOP);
        } else {
          log.info("{}: maximum deceleration because of a reading inside the clearance", getName());
        }
        desired.setTransDecel(emergencyDecel(robot));
      }
      lastStopped = true;
      if (forwards) {
        desired.setMaxVel(0);
      } else {
        desired.setMaxNegVel(0);
      }
      desired.setVel(0);
      if (stopRotationToo) {
        desired.setRotVel(0);
      }
      return desired;
    }

    double robotDecel = robot.getTransDecel();
    double stoppingDist = robotDecel > 0 ? absVel * absVel / 2.0 / robotDecel : 0;
    if (dist > stoppingDist) {
      return null;
    }
    lastStopped = false;
    double deceleration = absVel * absVel / dist / 2.0;
    double decelerationInner = absVel * absVel / distInner / 2.0;
    boolean moreThanRobot = Math.abs(deceleration) > Math.abs(robotDecel);
    boolean moreThanOthers =
        currentDesired.getTransDecelStrength() < ArActionDesired.MIN_STRENGTH
            || Math.abs(deceleration) > Math.abs(currentDesired.getTransDecel());
    if (moreThanRobot && moreThanOthers) {
      double decelDesired;
      if (Math.abs(maxEmergencyDecel) > 1 && Math.abs(decelerationInner) > maxEmergencyDecel) {
        decelDesired = maxEmergencyDecel;
      } else if (Math.abs(decelerationInner) > preferredDecel) {
        decelDesired = Math.abs(decelerationInner);
      } else if (Math.abs(maxEmergencyDecel) > 1 && Math.abs(deceleration) > maxEmergencyDecel) {
        decelDesired = maxEmergencyDecel;
      } else if (Math.abs(deceleration) > preferredDecel) {
        decelDesired = preferredDecel;
      } else {
        decelDesired = Math.abs(deceleration);
      }
      desired.setTransDecel(decelDesired);
    }
    if (forwards) {
      desired.setMaxVel(0);
    } else {
      desired.setMaxNegVel(0);
    }
    return desired;
  }

  private double emergencyDecel(ArRobot robot) {
    if (Math.abs(maxEmergencyDecel) > 1) {
      return maxEmergencyDecel;
    }
    ArConfigPacket config = robot.getOrigRobotConfig();
    if (config != null && config.getInt(ArConfigPacket.Field.TRANS_ACCEL_TOP) > 0) {
      return config.getInt(ArConfigPacket.Field.TRANS_ACCEL_TOP);
    }
    return preferredDecel;
  }

  /** Whether the last cycle stopped the robot for a reading inside the clearance. */
  public boolean getLastStopped() {
    return lockedGet(() -> lastStopped);
  }
}
