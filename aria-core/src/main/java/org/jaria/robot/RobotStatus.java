package org.jaria.robot;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.range.ArSensorReading;

/**
 * Everything the robot reported in one standard SIP, already converted to millimetres, degrees and
 * volts. ArRobot publishes a new status after every SIP; a status never changes, so a program that
 * reads one sees a consistent picture (pose, speeds and sonar from the same packet) without
 * locking.
 *
 * @param counter the robot's cycle counter when the SIP was processed
 * @param timeNanos clock time the SIP was processed
 * @param pose global pose (odometry corrected by the encoder→global transform)
 * @param encoderPose odometry pose (after gyro correction, if any)
 * @param rawEncoderPose odometry as the wheels report it
 * @param encoderTransform the encoder→global transform that made {@code pose} out of {@code
 *     encoderPose} (localization and {@code moveTo} set it)
 * @param vel translational velocity, mm/s
 * @param rotVel rotational velocity, deg/s
 * @param leftVel left wheel velocity, mm/s
 * @param rightVel right wheel velocity, mm/s
 * @param batteryVoltage battery voltage, V (SIP byte)
 * @param realBatteryVoltage battery voltage, V (16-bit field when present)
 * @param stallValue stall bits (0 left, 8 right) and bumper bits
 * @param control heading setpoint relative to the current heading, degrees
 * @param flags SIP flags word
 * @param compass compass heading, degrees (0 if none)
 * @param anPort selected analog port
 * @param analog selected analog input, 0..255
 * @param digIn digital inputs
 * @param digOut digital outputs
 * @param gripState gripper state bits
 * @param chargeState −1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float
 * @param faultFlags fault flags (0 if the firmware does not send them)
 * @param moving whether the SIP said the robot is moving (ID 0x33)
 * @param odometerDistance total distance driven since connecting, mm
 * @param odometerDegrees total turning since connecting, degrees
 * @param sonars the latest reading of each sonar, indexed by sonar number
 */
public record RobotStatus(
    long counter,
    long timeNanos,
    ArPose pose,
    ArPose encoderPose,
    ArPose rawEncoderPose,
    ArTransform encoderTransform,
    double vel,
    double rotVel,
    double leftVel,
    double rightVel,
    double batteryVoltage,
    double realBatteryVoltage,
    int stallValue,
    double control,
    int flags,
    int compass,
    int anPort,
    int analog,
    int digIn,
    int digOut,
    int gripState,
    int chargeState,
    int faultFlags,
    boolean moving,
    double odometerDistance,
    double odometerDegrees,
    List<ArSensorReading> sonars) {

  /** Copies the sonar list so the status cannot change afterwards. */
  public RobotStatus {
    sonars = List.copyOf(sonars);
  }

  /** The status before any SIP: at the origin, nothing known. */
  public static RobotStatus initial(List<ArSensorReading> sonars) {
    return builder().counter(-1).chargeState(-1).sonars(sonars).build();
  }

  /** A builder with every field zero (poses at the origin, no sonar). */
  public static Builder builder() {
    return new Builder();
  }

  /** A builder holding this status's values, to make a changed copy. */
  public Builder toBuilder() {
    return new Builder()
        .counter(counter)
        .timeNanos(timeNanos)
        .pose(pose)
        .encoderPose(encoderPose)
        .rawEncoderPose(rawEncoderPose)
        .encoderTransform(encoderTransform)
        .wheelVels(leftVel, rightVel)
        .vel(vel)
        .rotVel(rotVel)
        .batteryVoltage(batteryVoltage)
        .realBatteryVoltage(realBatteryVoltage)
        .stallValue(stallValue)
        .control(control)
        .flags(flags)
        .compass(compass)
        .anPort(anPort)
        .analog(analog)
        .digIn(digIn)
        .digOut(digOut)
        .gripState(gripState)
        .chargeState(chargeState)
        .faultFlags(faultFlags)
        .moving(moving)
        .odometer(odometerDistance, odometerDegrees)
        .sonars(sonars);
  }

  /**
   * The same status with another global pose, the transform that made it, and sonar readings (after
   * a relocalization).
   */
  RobotStatus relocalized(
      ArPose newPose, ArTransform newTransform, List<ArSensorReading> newSonars) {
    return toBuilder().pose(newPose).encoderTransform(newTransform).sonars(newSonars).build();
  }

  /**
   * Builds a {@link RobotStatus} field by field, by name (the record has 27 components, too many to
   * pass by position without mixing two up). Each setter is named after the component it sets.
   */
  public static final class Builder {
    private long counter;
    private long timeNanos;
    private ArPose pose = ArPose.ORIGIN;
    private ArPose encoderPose = ArPose.ORIGIN;
    private ArPose rawEncoderPose = ArPose.ORIGIN;
    private ArTransform encoderTransform = ArTransform.IDENTITY;
    private double vel;
    private double rotVel;
    private double leftVel;
    private double rightVel;
    private double batteryVoltage;
    private double realBatteryVoltage;
    private int stallValue;
    private double control;
    private int flags;
    private int compass;
    private int anPort;
    private int analog;
    private int digIn;
    private int digOut;
    private int gripState;
    private int chargeState;
    private int faultFlags;
    private boolean moving;
    private double odometerDistance;
    private double odometerDegrees;
    private List<ArSensorReading> sonars = List.of();

    private Builder() {}

    /** See {@link RobotStatus#counter()}. */
    public Builder counter(long v) {
      counter = v;
      return this;
    }

    /** See {@link RobotStatus#timeNanos()}. */
    public Builder timeNanos(long v) {
      timeNanos = v;
      return this;
    }

    /** See {@link RobotStatus#pose()}. */
    public Builder pose(ArPose v) {
      pose = v;
      return this;
    }

    /** See {@link RobotStatus#encoderPose()}. */
    public Builder encoderPose(ArPose v) {
      encoderPose = v;
      return this;
    }

    /** See {@link RobotStatus#rawEncoderPose()}. */
    public Builder rawEncoderPose(ArPose v) {
      rawEncoderPose = v;
      return this;
    }

    /** See {@link RobotStatus#encoderTransform()}. */
    public Builder encoderTransform(ArTransform v) {
      encoderTransform = v;
      return this;
    }

    /** See {@link RobotStatus#vel()}. */
    public Builder vel(double v) {
      vel = v;
      return this;
    }

    /** See {@link RobotStatus#rotVel()}. */
    public Builder rotVel(double v) {
      rotVel = v;
      return this;
    }

    /** See {@link RobotStatus#leftVel()} and {@link RobotStatus#rightVel()}. */
    public Builder wheelVels(double left, double right) {
      leftVel = left;
      rightVel = right;
      return this;
    }

    /** See {@link RobotStatus#batteryVoltage()}. */
    public Builder batteryVoltage(double v) {
      batteryVoltage = v;
      return this;
    }

    /** See {@link RobotStatus#realBatteryVoltage()}. */
    public Builder realBatteryVoltage(double v) {
      realBatteryVoltage = v;
      return this;
    }

    /** See {@link RobotStatus#stallValue()}. */
    public Builder stallValue(int v) {
      stallValue = v;
      return this;
    }

    /** See {@link RobotStatus#control()}. */
    public Builder control(double v) {
      control = v;
      return this;
    }

    /** See {@link RobotStatus#flags()}. */
    public Builder flags(int v) {
      flags = v;
      return this;
    }

    /** See {@link RobotStatus#compass()}. */
    public Builder compass(int v) {
      compass = v;
      return this;
    }

    /** See {@link RobotStatus#anPort()}. */
    public Builder anPort(int v) {
      anPort = v;
      return this;
    }

    /** See {@link RobotStatus#analog()}. */
    public Builder analog(int v) {
      analog = v;
      return this;
    }

    /** See {@link RobotStatus#digIn()}. */
    public Builder digIn(int v) {
      digIn = v;
      return this;
    }

    /** See {@link RobotStatus#digOut()}. */
    public Builder digOut(int v) {
      digOut = v;
      return this;
    }

    /** See {@link RobotStatus#gripState()}. */
    public Builder gripState(int v) {
      gripState = v;
      return this;
    }

    /** See {@link RobotStatus#chargeState()}. */
    public Builder chargeState(int v) {
      chargeState = v;
      return this;
    }

    /** See {@link RobotStatus#faultFlags()}. */
    public Builder faultFlags(int v) {
      faultFlags = v;
      return this;
    }

    /** See {@link RobotStatus#moving()}. */
    public Builder moving(boolean v) {
      moving = v;
      return this;
    }

    /** See {@link RobotStatus#odometerDistance()} and {@link RobotStatus#odometerDegrees()}. */
    public Builder odometer(double distance, double degrees) {
      odometerDistance = distance;
      odometerDegrees = degrees;
      return this;
    }

    /** See {@link RobotStatus#sonars()}; copied when the status is built. */
    public Builder sonars(List<ArSensorReading> v) {
      sonars = v;
      return this;
    }

    /** The status with the values set so far. */
    public RobotStatus build() {
      return new RobotStatus(
          counter,
          timeNanos,
          pose,
          encoderPose,
          rawEncoderPose,
          encoderTransform,
          vel,
          rotVel,
          leftVel,
          rightVel,
          batteryVoltage,
          realBatteryVoltage,
          stallValue,
          control,
          flags,
          compass,
          anPort,
          analog,
          digIn,
          digOut,
          gripState,
          chargeState,
          faultFlags,
          moving,
          odometerDistance,
          odometerDegrees,
          sonars);
    }
  }
}
