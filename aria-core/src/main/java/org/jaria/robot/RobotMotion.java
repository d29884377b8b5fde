package org.jaria.robot;

import org.jaria.clock.Clock;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropCounters;

/**
 * Commanding the robot: motion commands (kept and re-sent by state reflection), direct commands
 * (sent at once), and the speed and acceleration limits. Part of {@link ArRobot}'s API; use it
 * through ArRobot. Every method may be called from any thread.
 *
 * <p>Motion commands and actions share the wheels: a motion command takes precedence over actions
 * (for its axis, translation or rotation) until {@link #clearDirectMotion()} or, if set, for the
 * {@link #setDirectMotionPrecedenceTime direct-motion precedence time}.
 */
public abstract class RobotMotion extends RobotState {

  final ArRobotPacketSender sender;
  final StateReflector motion;

  RobotMotion(Clock clock, ArRobotParams params, DropCounters drops) {
    super(clock, params, drops);
    this.sender = new ArRobotPacketSender(clock);
    this.motion = new StateReflector(clock, sender, this::getStatus);
  }

  // ---------------------------------------------------------------- motion commands

  /** Drives at {@code mmPerSec} (negative backwards). */
  public void setVel(double mmPerSec) {
    motion.setVel(mmPerSec);
  }

  /** Drives each wheel at its own speed, mm/s (sent as VEL2, in Vel2Divisor steps). */
  public void setVel2(double leftMmPerSec, double rightMmPerSec) {
    motion.setVel2(leftMmPerSec, rightMmPerSec);
  }

  /** Turns at {@code degPerSec} (+ counter-clockwise). */
  public void setRotVel(double degPerSec) {
    motion.setRotVel(degPerSec);
  }

  /** Turns to the global heading {@code degrees}, the shorter way round. */
  public void setHeading(double degrees) {
    motion.setHeading(degrees);
  }

  /** Turns by {@code degrees} from the current heading (+ counter-clockwise). */
  public void setDeltaHeading(double degrees) {
    motion.setDeltaHeading(degrees);
  }

  /** Drives {@code mm} forward (negative backwards) and stops. */
  public void move(double mm) {
    motion.move(mm);
  }

  /** Whether the last {@link #move} is done, within the move-done distance (default 40 mm). */
  public boolean isMoveDone() {
    return motion.isMoveDone(0);
  }

  /** Whether the last {@link #move} is done within {@code delta} mm. */
  public boolean isMoveDone(double delta) {
    return motion.isMoveDone(delta);
  }

  /** Whether the last heading command is done, within the heading-done difference (3°). */
  public boolean isHeadingDone() {
    return motion.isHeadingDone(0);
  }

  /** Whether the last heading command is done within {@code delta} degrees. */
  public boolean isHeadingDone(double delta) {
    return motion.isHeadingDone(delta);
  }

  /** Sets the default tolerance of {@link #isMoveDone()}, mm. */
  public void setMoveDoneDist(double mm) {
    motion.setMoveDoneDist(mm);
  }

  /** The default tolerance of {@link #isMoveDone()}, mm. */
  public double getMoveDoneDist() {
    return motion.getMoveDoneDist();
  }

  /** Sets the default tolerance of {@link #isHeadingDone()}, degrees. */
  public void setHeadingDoneDiff(double degrees) {
    motion.setHeadingDoneDiff(degrees);
  }

  /** The default tolerance of {@link #isHeadingDone()}, degrees. */
  public double getHeadingDoneDiff() {
    return motion.getHeadingDoneDiff();
  }

  /** Stops translation and rotation now (STOP), and keeps asking for zero speed. */
  public void stop() {
    motion.stop();
  }

  /** Gives the wheels back to the actions: forgets the motion commands. */
  public void clearDirectMotion() {
    motion.clearDirectMotion();
  }

  /** Whether motion commands currently take precedence over actions. */
  public boolean isDirectMotion() {
    return motion.isDirectMotion();
  }

  /**
   * How long a motion command keeps precedence over actions, ms; 0 (the default) means until {@link
   * #clearDirectMotion()}.
   */
  public void setDirectMotionPrecedenceTime(long ms) {
    motion.setDirectMotionPrecedenceTime(ms);
  }

  /** The direct-motion precedence time, ms (0 = until cleared). */
  public long getDirectMotionPrecedenceTime() {
    return motion.getDirectMotionPrecedenceTime();
  }

  /** How often unchanged motion commands are re-sent, ms (default 500). */
  public void setStateReflectionRefreshTime(long ms) {
    motion.setRefreshMillis(ms);
  }

  /** The state-reflection refresh time, ms. */
  public long getStateReflectionRefreshTime() {
    return motion.getRefreshMillis();
  }

  /** Whether the last cycle's commands asked the robot to move. */
  public boolean isTryingToMove() {
    return motion.isTryingToMove();
  }

  // ---------------------------------------------------------------- limits

  /** Maximum translational velocity for motion commands and actions, mm/s. */
  public boolean setTransVelMax(double mmPerSec) {
    return motion.limits().setTransVelMax(mmPerSec);
  }

  /** The maximum translational velocity, mm/s. */
  public double getTransVelMax() {
    return motion.limits().getTransVelMax();
  }

  /** Maximum rotational velocity, deg/s. */
  public boolean setRotVelMax(double degPerSec) {
    return motion.limits().setRotVelMax(degPerSec);
  }

  /** The maximum rotational velocity, deg/s. */
  public double getRotVelMax() {
    return motion.limits().getRotVelMax();
  }

  /** Translational acceleration, mm/s². */
  public void setTransAccel(double a) {
    motion.limits().setTransAccel(a);
  }

  /** The translational acceleration, mm/s². */
  public double getTransAccel() {
    return motion.limits().getTransAccel();
  }

  /** Translational deceleration, mm/s². */
  public void setTransDecel(double a) {
    motion.limits().setTransDecel(a);
  }

  /** The translational deceleration, mm/s². */
  public double getTransDecel() {
    return motion.limits().getTransDecel();
  }

  /** Rotational acceleration, deg/s². */
  public void setRotAccel(double a) {
    motion.limits().setRotAccel(a);
  }

  /** The rotational acceleration, deg/s². */
  public double getRotAccel() {
    return motion.limits().getRotAccel();
  }

  /** Rotational deceleration, deg/s². */
  public void setRotDecel(double a) {
    motion.limits().setRotDecel(a);
  }

  /** The rotational deceleration, deg/s². */
  public double getRotDecel() {
    return motion.limits().getRotDecel();
  }

  /** The top translational velocity this robot allows, mm/s (from CONFIGpac or parameters). */
  public double getAbsoluteMaxTransVel() {
    return motion.limits().getAbsoluteMaxTransVel();
  }

  /** Lowers (or raises) the top translational velocity. */
  public void setAbsoluteMaxTransVel(double mmPerSec) {
    motion.limits().setAbsoluteMaxTransVel(mmPerSec);
  }

  /** The top rotational velocity this robot allows, deg/s. */
  public double getAbsoluteMaxRotVel() {
    return motion.limits().getAbsoluteMaxRotVel();
  }

  /** Lowers (or raises) the top rotational velocity. */
  public void setAbsoluteMaxRotVel(double degPerSec) {
    motion.limits().setAbsoluteMaxRotVel(degPerSec);
  }

  // ---------------------------------------------------------------- direct commands

  /** Sends a command without argument now. */
  public boolean com(int command) {
    return sender.com(command);
  }

  /** Sends a command without argument now. */
  public boolean com(ArCommands command) {
    return sender.com(command.getNumber());
  }

  /** Sends a command with an integer argument now. */
  public boolean comInt(int command, int argument) {
    return sender.comInt(command, argument);
  }

  /** Sends a command with an integer argument now. */
  public boolean comInt(ArCommands command, int argument) {
    return sender.comInt(command.getNumber(), argument);
  }

  /** Sends a two-byte command (high, low) now. */
  public boolean com2Bytes(int command, int high, int low) {
    return sender.com2Bytes(command, high, low);
  }

  /** Sends a two-byte command (high, low) now. */
  public boolean com2Bytes(ArCommands command, int high, int low) {
    return sender.com2Bytes(command.getNumber(), high, low);
  }

  /** Sends a string command now. */
  public boolean comStr(int command, String argument) {
    return sender.comStr(command, argument);
  }

  /** Sends a string command now. */
  public boolean comStr(ArCommands command, String argument) {
    return sender.comStr(command.getNumber(), argument);
  }

  /**
   * Sends a string command with exactly {@code size} bytes now (ARIA's {@code comStrN}): the string
   * is cut or padded with NULs to {@code size}.
   */
  public boolean comStrN(int command, String argument, int size) {
    return sender.comStrN(command, argument, size);
  }

  /** Sends a string command with exactly {@code size} bytes now. */
  public boolean comStrN(ArCommands command, String argument, int size) {
    return sender.comStrN(command.getNumber(), argument, size);
  }

  /** Sends a command whose string argument is raw bytes (SAY's note pairs, TTY2 data). */
  public boolean comDataN(ArCommands command, byte[] data) {
    return sender.comDataN(command.getNumber(), data, 0, data.length);
  }

  /** Sends a packet you built and finalized yourself. */
  public boolean sendPacket(ArRobotPacket packet) {
    return sender.sendPacket(packet);
  }

  /** Turns the motors on (ENABLE 1). */
  public boolean enableMotors() {
    return sender.comInt(ArCommands.ENABLE.getNumber(), 1);
  }

  /** Turns the motors off (ENABLE 0). */
  public boolean disableMotors() {
    return sender.comInt(ArCommands.ENABLE.getNumber(), 0);
  }

  /** Turns all sonar arrays on. */
  public boolean enableSonar() {
    return sender.comInt(ArCommands.SONAR.getNumber(), 1);
  }

  /** Turns all sonar arrays off. */
  public boolean disableSonar() {
    return sender.comInt(ArCommands.SONAR.getNumber(), 0);
  }

  /** Asks for a continuous stream of ENCODERpacs. */
  public boolean requestEncoderPackets() {
    return sender.comInt(ArCommands.ENCODER.getNumber(), 2);
  }

  /** Stops the ENCODERpac stream. */
  public boolean stopEncoderPackets() {
    return sender.comInt(ArCommands.ENCODER.getNumber(), 0);
  }

  /** Asks for a continuous stream of IOpacs. */
  public boolean requestIOPackets() {
    return sender.comInt(ArCommands.IOREQUEST.getNumber(), 2);
  }

  /** Stops the IOpac stream. */
  public boolean stopIOPackets() {
    return sender.comInt(ArCommands.IOREQUEST.getNumber(), 0);
  }
}
