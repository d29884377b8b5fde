package org.jaria.robot;

import java.util.List;
import org.jaria.geom.ArPose;
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
    return new RobotStatus(
        -1,
        0,
        ArPose.ORIGIN,
        ArPose.ORIGIN,
        ArPose.ORIGIN,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        0,
        -1,
        0,
        false,
        0,
        0,
        sonars);
  }

  /** The same status with another global pose and sonar readings (after a relocalization). */
  RobotStatus withPoseAndSonars(ArPose newPose, List<ArSensorReading> newSonars) {
    return new RobotStatus(
        counter,
        timeNanos,
        newPose,
        encoderPose,
        rawEncoderPose,
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
        newSonars);
  }
}
