package org.jaria.net.data;

import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * The robot's state as a monitor shows it ({@code "update"}, ArNetworking's {@code updateNumbers}
 * and {@code updateStrings} in one).
 *
 * @param mode the active server mode ("Stop", "Drive", "Wander", "Goto" ...)
 * @param status what the mode is doing ("Stopped", "Going to goal A" ...)
 * @param batteryVoltage volts
 * @param x global x, mm
 * @param y global y, mm
 * @param th heading, degrees (-180, 180]
 * @param vel translational velocity, mm/s
 * @param rotVel rotational velocity, deg/s
 * @param leftVel left wheel, mm/s
 * @param rightVel right wheel, mm/s
 * @param motorsEnabled whether the motors are on
 * @param leftStalled left motor stalled
 * @param rightStalled right motor stalled
 * @param eStop the emergency stop is pressed
 * @param chargeState -1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float
 * @param counter the robot's cycle counter during the cycle that took this snapshot (one less than
 *     {@code ArRobot.getCounter()} once that cycle has ended)
 */
public record RobotUpdate(
    String mode,
    String status,
    double batteryVoltage,
    double x,
    double y,
    double th,
    double vel,
    double rotVel,
    double leftVel,
    double rightVel,
    boolean motorsEnabled,
    boolean leftStalled,
    boolean rightStalled,
    boolean eStop,
    int chargeState,
    long counter)
    implements NetEncodable {

  private static final int FIELDS = 16;

  /** The pose. */
  public ArPose getPose() {
    return new ArPose(x, y, th);
  }

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS)
        .strToBuf(mode)
        .strToBuf(status)
        .doubleToBuf(batteryVoltage)
        .doubleToBuf(x)
        .doubleToBuf(y)
        .doubleToBuf(th)
        .doubleToBuf(vel)
        .doubleToBuf(rotVel)
        .doubleToBuf(leftVel)
        .doubleToBuf(rightVel)
        .boolToBuf(motorsEnabled)
        .boolToBuf(leftStalled)
        .boolToBuf(rightStalled)
        .boolToBuf(eStop)
        .intToBuf(chargeState)
        .intToBuf(counter);
  }

  /** Reads what {@link #write} wrote. */
  public static RobotUpdate read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "a robot update");
    RobotUpdate u =
        new RobotUpdate(
            in.bufToStr(),
            in.bufToStr(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToBool(),
            in.bufToBool(),
            in.bufToBool(),
            in.bufToBool(),
            in.bufToInt(),
            in.bufToLong());
    Fields.end(in, n, FIELDS);
    return u;
  }
}
