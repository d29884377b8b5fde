package org.jaria.robot;

import java.util.List;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.range.ArSensorReading;

/**
 * What the robot reports and what it is: {@link ArRobot}'s getters for the latest SIP (pose,
 * velocities, battery, bumpers, flags, inputs, sonar) and for the robot's size from its parameters.
 *
 * <p>Each getter is a plain function of two values, the immutable {@link #getStatus() status} the
 * last SIP produced and the {@link #getRobotParams() parameters} in use, so it may be called from
 * any thread and two getters called one after the other may see two different SIPs; read {@link
 * #getStatus()} once when several fields must agree. {@link ArRobot} is the only implementation:
 * this interface keeps the readings, one job of ARIA's large {@code ArRobot} API, in a file of
 * their own.
 */
public sealed interface RobotReadings permits ArRobot {

  /** Everything the last SIP said, as one consistent snapshot. */
  RobotStatus getStatus();

  /** The parameters in use (from the robot's subtype and name once connected). */
  ArRobotParams getRobotParams();

  /** Global pose: odometry corrected by the encoder→global transform (localization). */
  default ArPose getPose() {
    return getStatus().pose();
  }

  /** Global x, mm. */
  default double getX() {
    return getStatus().pose().x();
  }

  /** Global y, mm. */
  default double getY() {
    return getStatus().pose().y();
  }

  /** Global heading, degrees in (−180, 180]. */
  default double getTh() {
    return getStatus().pose().th();
  }

  /** Odometry pose (corrected by a gyro if one is attached). */
  default ArPose getEncoderPose() {
    return getStatus().encoderPose();
  }

  /** Odometry pose exactly as the wheels report it. */
  default ArPose getRawEncoderPose() {
    return getStatus().rawEncoderPose();
  }

  /** Translational velocity, mm/s. */
  default double getVel() {
    return getStatus().vel();
  }

  /** Rotational velocity, deg/s (+ counter-clockwise). */
  default double getRotVel() {
    return getStatus().rotVel();
  }

  /** Left wheel velocity, mm/s. */
  default double getLeftVel() {
    return getStatus().leftVel();
  }

  /** Right wheel velocity, mm/s. */
  default double getRightVel() {
    return getStatus().rightVel();
  }

  /** Battery voltage, V. */
  default double getBatteryVoltage() {
    return getStatus().batteryVoltage();
  }

  /** Battery voltage from the 16-bit field (for batteries above 25.5 V), V. */
  default double getRealBatteryVoltage() {
    return getStatus().realBatteryVoltage();
  }

  /** The raw stall and bumper word: bit 0 left stall, bit 8 right stall, others bumpers. */
  default int getStallValue() {
    return getStatus().stallValue();
  }

  /** Whether the left motor is stalled. */
  default boolean isLeftMotorStalled() {
    return (getStatus().stallValue() & 0x1) != 0;
  }

  /** Whether the right motor is stalled. */
  default boolean isRightMotorStalled() {
    return (getStatus().stallValue() & 0x100) != 0;
  }

  /**
   * Front bumper bits: bits 9..15 of the stall word (the right motor's byte, as ARIA reads it),
   * shifted down so that bumper 0 — the leftmost — is bit 0.
   */
  default int getFrontBumpers() {
    return (getStatus().stallValue() >> 9) & 0x7F;
  }

  /** Rear bumper bits: bits 1..7 of the stall word, shifted down so bumper 0 is bit 0. */
  default int getRearBumpers() {
    return (getStatus().stallValue() >> 1) & 0x7F;
  }

  /** Heading setpoint relative to the current heading, degrees. */
  default double getControl() {
    return getStatus().control();
  }

  /** The SIP flags word. */
  default int getFlags() {
    return getStatus().flags();
  }

  /** Whether the motors are enabled. */
  default boolean areMotorsEnabled() {
    return (getStatus().flags() & 0x1) != 0;
  }

  /** Whether any sonar array is enabled. */
  default boolean areSonarsEnabled() {
    return (getStatus().flags() & 0x1E) != 0;
  }

  /** Whether the emergency stop button is pressed. */
  default boolean isEStopPressed() {
    return (getStatus().flags() & 0x20) != 0;
  }

  /** Whether the robot says it is moving (SIP type 0x33). */
  default boolean isMoving() {
    return getStatus().moving();
  }

  /** Compass heading, degrees (0 when there is no compass). */
  default int getCompass() {
    return getStatus().compass();
  }

  /** The analog port selected with ADSEL. */
  default int getAnalogPortSelected() {
    return getStatus().anPort();
  }

  /** The selected analog input, 0..255 for 0..5 V. */
  default int getAnalog() {
    return getStatus().analog();
  }

  /** The digital inputs byte. */
  default int getDigIn() {
    return getStatus().digIn();
  }

  /** The digital outputs byte. */
  default int getDigOut() {
    return getStatus().digOut();
  }

  /** Gripper state bits (see {@link org.jaria.protocol.packets.GripState}). */
  default int getGripState() {
    return getStatus().gripState();
  }

  /** Charge state: −1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float. */
  default int getChargeState() {
    return getStatus().chargeState();
  }

  /** Fault flags (0 when the firmware does not report them). */
  default int getFaultFlags() {
    return getStatus().faultFlags();
  }

  /** Distance driven since connecting, mm. */
  default double getOdometerDistance() {
    return getStatus().odometerDistance();
  }

  /** Degrees turned since connecting. */
  default double getOdometerDegrees() {
    return getStatus().odometerDegrees();
  }

  // ---------------------------------------------------------------- sonar

  /** Number of sonar transducers, from the robot's parameters. */
  default int getNumSonar() {
    return getStatus().sonars().size();
  }

  /** Range of sonar {@code num}, mm; −1 if it never reported or does not exist. */
  default int getSonarRange(int num) {
    List<ArSensorReading> s = getStatus().sonars();
    return num >= 0 && num < s.size() ? s.get(num).range() : -1;
  }

  /** Whether sonar {@code num} reported in the SIP of the current cycle. */
  default boolean isSonarNew(int num) {
    RobotStatus st = getStatus();
    List<ArSensorReading> s = st.sonars();
    return num >= 0 && num < s.size() && s.get(num).counterTaken() == st.counter();
  }

  /** The latest reading of sonar {@code num}, or null if there is no such sonar. */
  default ArSensorReading getSonarReading(int num) {
    List<ArSensorReading> s = getStatus().sonars();
    return num >= 0 && num < s.size() ? s.get(num) : null;
  }

  /**
   * The number of the sonar with the shortest range among those facing between {@code startAngle}
   * and {@code endAngle} (counter-clockwise, degrees); −1 if none faces there.
   */
  default int getClosestSonarNumber(double startAngle, double endAngle) {
    List<ArSensorReading> s = getStatus().sonars();
    int best = -1;
    int bestRange = 0;
    for (int i = 0; i < s.size(); i++) {
      ArSensorReading r = s.get(i);
      // Sonars that never reported (range -1) are not "closest" (ARIA would pick them).
      if (r.range() >= 0
          && angleBetween(r.sensorTh(), startAngle, endAngle)
          && (best < 0 || r.range() < bestRange)) {
        best = i;
        bestRange = r.range();
      }
    }
    return best;
  }

  /** The shortest range among sonars facing between the angles, mm; −1 if none. */
  default int getClosestSonarRange(double startAngle, double endAngle) {
    int n = getClosestSonarNumber(startAngle, endAngle);
    return n < 0 ? -1 : getSonarRange(n);
  }

  /**
   * Whether {@code angle} lies in the sector from {@code start} counter-clockwise to {@code end}.
   */
  private static boolean angleBetween(double angle, double start, double end) {
    angle = ArMath.fixAngle(angle);
    start = ArMath.fixAngle(start);
    end = ArMath.fixAngle(end);
    if (start < end) {
      return angle >= start && angle <= end;
    }
    return angle >= start || angle <= end;
  }

  // ---------------------------------------------------------------- geometry from parameters

  /** Robot radius, mm (from the parameters). */
  default double getRobotRadius() {
    return getRobotParams().getRobotRadius();
  }

  /** Robot width, mm. */
  default double getRobotWidth() {
    return getRobotParams().getRobotWidth();
  }

  /** Robot length, mm. */
  default double getRobotLength() {
    return getRobotParams().getRobotLength();
  }

  /** Distance from the centre of rotation to the front, mm. */
  default double getRobotLengthFront() {
    return getRobotParams().getRobotLengthFront();
  }

  /** Distance from the centre of rotation to the rear, mm. */
  default double getRobotLengthRear() {
    return getRobotParams().getRobotLengthRear();
  }

  /** The transform from the robot's local frame to global coordinates (at the current pose). */
  default ArTransform getToGlobalTransform() {
    return ArTransform.ofPose(getPose());
  }

  /** The transform from global coordinates to the robot's local frame. */
  default ArTransform getToLocalTransform() {
    return getToGlobalTransform().inverse();
  }
}
