package org.jaria.robot;

import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.EncoderPacket;
import org.jaria.protocol.packets.IoPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.range.ArSensorReading;

/**
 * The robot's reflected state: what the last SIP said, converted to millimetres, degrees and volts
 * (ARIA's state reflection getters). Part of {@link ArRobot}'s API; use it through ArRobot.
 *
 * <p>Every getter reads the latest published {@link RobotStatus} and may be called from any thread.
 * To read several values from one and the same SIP, take {@link #getStatus()} once.
 */
public abstract class RobotState {

  /** The clock every wait and timeout of this robot uses. */
  protected final Clock clock;

  volatile ArRobotParams params;
  final SipProcessor processor;
  private final DropCounters drops;
  private final StandardSip sip = new StandardSip();
  private volatile RobotStatus status;
  private volatile EncoderPacket encoders = new EncoderPacket(0, 0);
  private volatile IoPacket io = new IoPacket(new int[0], new int[0], new int[0]);

  RobotState(Clock clock, ArRobotParams params, DropCounters drops) {
    this.clock = clock;
    this.drops = drops;
    this.params = params;
    this.processor = new SipProcessor(params);
    this.status = processor.last();
  }

  /** The clock this robot runs on. */
  public Clock getClock() {
    return clock;
  }

  void setParams(ArRobotParams p) {
    params = p;
    processor.setParams(p);
    status = processor.last();
  }

  void resetState() {
    processor.reset();
    status = processor.last();
  }

  void publish(RobotStatus s) {
    status = s;
  }

  /** Standard SIP handler: decodes it and publishes a new status. */
  boolean handleSip(ArRobotPacket p, long counter) {
    if (!PacketIds.isStandardSip(p.getID())) {
      return false;
    }
    if (!sip.decode(p)) {
      drops.drop(DropReason.MALFORMED, "short standard SIP");
      return true;
    }
    publish(processor.process(sip, counter, clock.nanoTime()));
    return true;
  }

  boolean handleEncoderPacket(ArRobotPacket p) {
    if (p.getID() != PacketIds.ENCODER) {
      return false;
    }
    EncoderPacket e = EncoderPacket.decode(p);
    if (e == null) {
      drops.drop(DropReason.MALFORMED, "short ENCODERpac");
    } else {
      encoders = e;
    }
    return true;
  }

  boolean handleIoPacket(ArRobotPacket p) {
    if (p.getID() != PacketIds.IO) {
      return false;
    }
    IoPacket q = IoPacket.decode(p);
    if (q == null) {
      drops.drop(DropReason.MALFORMED, "short IOpac");
    } else {
      io = q;
    }
    return true;
  }

  /** Packets dropped on the way in, by reason. */
  public DropCounters getDropCounters() {
    return drops;
  }

  /** Everything the last SIP said, as one consistent snapshot. */
  public RobotStatus getStatus() {
    return status;
  }

  /** Global pose: odometry corrected by the encoder→global transform (localization). */
  public ArPose getPose() {
    return status.pose();
  }

  /** Global x, mm. */
  public double getX() {
    return status.pose().x();
  }

  /** Global y, mm. */
  public double getY() {
    return status.pose().y();
  }

  /** Global heading, degrees in (−180, 180]. */
  public double getTh() {
    return status.pose().th();
  }

  /** Odometry pose (corrected by a gyro if one is attached). */
  public ArPose getEncoderPose() {
    return status.encoderPose();
  }

  /** Odometry pose exactly as the wheels report it. */
  public ArPose getRawEncoderPose() {
    return status.rawEncoderPose();
  }

  /** Translational velocity, mm/s. */
  public double getVel() {
    return status.vel();
  }

  /** Rotational velocity, deg/s (+ counter-clockwise). */
  public double getRotVel() {
    return status.rotVel();
  }

  /** Left wheel velocity, mm/s. */
  public double getLeftVel() {
    return status.leftVel();
  }

  /** Right wheel velocity, mm/s. */
  public double getRightVel() {
    return status.rightVel();
  }

  /** Battery voltage, V. */
  public double getBatteryVoltage() {
    return status.batteryVoltage();
  }

  /** Battery voltage from the 16-bit field (for batteries above 25.5 V), V. */
  public double getRealBatteryVoltage() {
    return status.realBatteryVoltage();
  }

  /** The raw stall and bumper word: bit 0 left stall, bit 8 right stall, others bumpers. */
  public int getStallValue() {
    return status.stallValue();
  }

  /** Whether the left motor is stalled. */
  public boolean isLeftMotorStalled() {
    return (status.stallValue() & 0x1) != 0;
  }

  /** Whether the right motor is stalled. */
  public boolean isRightMotorStalled() {
    return (status.stallValue() & 0x100) != 0;
  }

  /**
   * Front bumper bits: bits 9..15 of the stall word (the right motor's byte, as ARIA reads it),
   * shifted down so that bumper 0 — the leftmost — is bit 0.
   */
  public int getFrontBumpers() {
    return (status.stallValue() >> 9) & 0x7F;
  }

  /** Rear bumper bits: bits 1..7 of the stall word, shifted down so bumper 0 is bit 0. */
  public int getRearBumpers() {
    return (status.stallValue() >> 1) & 0x7F;
  }

  /** Heading setpoint relative to the current heading, degrees. */
  public double getControl() {
    return status.control();
  }

  /** The SIP flags word. */
  public int getFlags() {
    return status.flags();
  }

  /** Whether the motors are enabled. */
  public boolean areMotorsEnabled() {
    return (status.flags() & 0x1) != 0;
  }

  /** Whether any sonar array is enabled. */
  public boolean areSonarsEnabled() {
    return (status.flags() & 0x1E) != 0;
  }

  /** Whether the emergency stop button is pressed. */
  public boolean isEStopPressed() {
    return (status.flags() & 0x20) != 0;
  }

  /** Whether the robot says it is moving (SIP type 0x33). */
  public boolean isMoving() {
    return status.moving();
  }

  /** Compass heading, degrees (0 when there is no compass). */
  public int getCompass() {
    return status.compass();
  }

  /** The analog port selected with ADSEL. */
  public int getAnalogPortSelected() {
    return status.anPort();
  }

  /** The selected analog input, 0..255 for 0..5 V. */
  public int getAnalog() {
    return status.analog();
  }

  /** The digital inputs byte. */
  public int getDigIn() {
    return status.digIn();
  }

  /** The digital outputs byte. */
  public int getDigOut() {
    return status.digOut();
  }

  /** Gripper state bits (see {@link org.jaria.protocol.packets.GripState}). */
  public int getGripState() {
    return status.gripState();
  }

  /** Charge state: −1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float. */
  public int getChargeState() {
    return status.chargeState();
  }

  /** Fault flags (0 when the firmware does not report them). */
  public int getFaultFlags() {
    return status.faultFlags();
  }

  /** Distance driven since connecting, mm. */
  public double getOdometerDistance() {
    return status.odometerDistance();
  }

  /** Degrees turned since connecting. */
  public double getOdometerDegrees() {
    return status.odometerDegrees();
  }

  /** Left encoder count from the last ENCODERpac (request them first). */
  public int getLeftEncoder() {
    return encoders.left();
  }

  /** Right encoder count from the last ENCODERpac. */
  public int getRightEncoder() {
    return encoders.right();
  }

  /** Number of digital-input bytes in the last IOpac. */
  public int getIODigInSize() {
    return io.digIn().length;
  }

  /** Digital-input byte {@code n} of the last IOpac (request them first), 0 if absent. */
  public int getIODigIn(int n) {
    int[] v = io.digIn();
    return n >= 0 && n < v.length ? v[n] : 0;
  }

  /** Digital-output byte {@code n} of the last IOpac, 0 if absent. */
  public int getIODigOut(int n) {
    int[] v = io.digOut();
    return n >= 0 && n < v.length ? v[n] : 0;
  }

  /** Number of analog inputs in the last IOpac. */
  public int getIOAnalogSize() {
    return io.analog().length;
  }

  /** Analog input {@code n} of the last IOpac, 0..1023, 0 if absent. */
  public int getIOAnalog(int n) {
    int[] v = io.analog();
    return n >= 0 && n < v.length ? v[n] : 0;
  }

  // ---------------------------------------------------------------- sonar

  /** Number of sonar transducers, from the robot's parameters. */
  public int getNumSonar() {
    return status.sonars().size();
  }

  /** Range of sonar {@code num}, mm; −1 if it never reported or does not exist. */
  public int getSonarRange(int num) {
    List<ArSensorReading> s = status.sonars();
    return num >= 0 && num < s.size() ? s.get(num).range() : -1;
  }

  /** Whether sonar {@code num} reported in the SIP of the current cycle. */
  public boolean isSonarNew(int num) {
    List<ArSensorReading> s = status.sonars();
    return num >= 0 && num < s.size() && s.get(num).counterTaken() == status.counter();
  }

  /** The latest reading of sonar {@code num}, or null if there is no such sonar. */
  public ArSensorReading getSonarReading(int num) {
    List<ArSensorReading> s = status.sonars();
    return num >= 0 && num < s.size() ? s.get(num) : null;
  }

  /**
   * The number of the sonar with the shortest range among those facing between {@code startAngle}
   * and {@code endAngle} (counter-clockwise, degrees); −1 if none faces there.
   */
  public int getClosestSonarNumber(double startAngle, double endAngle) {
    List<ArSensorReading> s = status.sonars();
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
  public int getClosestSonarRange(double startAngle, double endAngle) {
    int n = getClosestSonarNumber(startAngle, endAngle);
    return n < 0 ? -1 : getSonarRange(n);
  }

  /**
   * Whether {@code angle} lies in the sector from {@code start} counter-clockwise to {@code end}.
   */
  static boolean angleBetween(double angle, double start, double end) {
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
  public double getRobotRadius() {
    return params.getRobotRadius();
  }

  /** Robot width, mm. */
  public double getRobotWidth() {
    return params.getRobotWidth();
  }

  /** Robot length, mm. */
  public double getRobotLength() {
    return params.getRobotLength();
  }

  /** Distance from the centre of rotation to the front, mm. */
  public double getRobotLengthFront() {
    return params.getRobotLengthFront();
  }

  /** Distance from the centre of rotation to the rear, mm. */
  public double getRobotLengthRear() {
    return params.getRobotLengthRear();
  }
}
