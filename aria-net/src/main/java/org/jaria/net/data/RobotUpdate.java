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

  /** The pose. */
  public ArPose getPose() {
    return new ArPose(x, y, th);
  }

  /**
   * Writes ArNetworking's "update" layout: string status; string mode; byte2 10 * battery volts;
   * byte4 x; byte4 y (mm); byte2 th (degrees, -179..180); byte2 vel; byte2 rotVel; byte2 latVel;
   * byte temperature (-128: unknown).
   */
  @Override
  public void write(ArNetPacket out) {
    out.strToBuf(status).strToBuf(mode);
    writeNumbers(out);
  }

  /** Writes ArNetworking's "updateNumbers" layout (the "update" layout without the strings). */
  public void writeNumbers(ArNetPacket out) {
    int deg = (int) Math.round(org.jaria.geom.ArMath.fixAngle(th));
    out.byte2ToBuf(clamp16(Math.round(batteryVoltage * 10)))
        .byte4ToBuf(clamp32(x))
        .byte4ToBuf(clamp32(y))
        .byte2ToBuf(deg == -180 ? 180 : deg)
        .byte2ToBuf(clamp16((long) vel))
        .byte2ToBuf(clamp16((long) rotVel))
        .byte2ToBuf(0)
        .byteToBuf(-128);
  }

  private static int clamp16(long v) {
    return (int) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, v));
  }

  private static int clamp32(double v) {
    return (int) Math.max(Integer.MIN_VALUE, Math.min(Integer.MAX_VALUE, v));
  }

  /**
   * Reads ArNetworking's "update" layout. Fields the layout does not carry get neutral values:
   * wheel speeds both {@code vel}, motors enabled, nothing stalled, no e-stop, charge state 0 and
   * counter 0.
   */
  public static RobotUpdate read(ArNetPacket in) {
    String status = in.bufToStr();
    String mode = in.bufToStr();
    return readNumbers(in, mode, status);
  }

  /** Reads ArNetworking's "updateNumbers" layout, with mode and status given. */
  public static RobotUpdate readNumbers(ArNetPacket in, String mode, String status) {
    double battery = in.bufToByte2() / 10.0;
    double x = in.bufToByte4();
    double y = in.bufToByte4();
    double th = in.bufToByte2();
    double vel = in.bufToByte2();
    double rotVel = in.bufToByte2();
    if (in.hasMore()) {
      in.bufToByte2(); // lateral velocity
    }
    if (in.hasMore()) {
      in.bufToByte(); // temperature
    }
    return new RobotUpdate(
        mode, status, battery, x, y, th, vel, rotVel, vel, vel, true, false, false, false, 0, 0);
  }
}
