package org.jaria.robot;

import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;

/**
 * Commands sent to the robot at once, outside the cycle: ARIA's {@code com}, {@code comInt}, {@code
 * comStr} ... and the switches built on them (motors, sonar, packet streams).
 *
 * <p>They go straight through the robot's one {@link #getPacketSender() packet sender}, from any
 * thread; each returns false if the packet could not be written (no open connection, or the write
 * failed). Motion commands are different: they are kept and re-sent by the cycle (see {@link
 * MotionCommands}). {@link ArRobot} is the only implementation: this interface keeps one job of
 * ARIA's large {@code ArRobot} API in a file of its own.
 */
public sealed interface RobotCommands permits ArRobot {

  /** The object that writes commands; its tap sees every packet sent. */
  ArRobotPacketSender getPacketSender();

  /** Commands sent since the robot was created. */
  default long getPacketsSent() {
    return getPacketSender().getPacketsSent();
  }

  /** Sends a command without argument now. */
  default boolean com(int command) {
    return getPacketSender().com(command);
  }

  /** Sends a command without argument now. */
  default boolean com(ArCommands command) {
    return getPacketSender().com(command.getNumber());
  }

  /** Sends a command with an integer argument now. */
  default boolean comInt(int command, int argument) {
    return getPacketSender().comInt(command, argument);
  }

  /** Sends a command with an integer argument now. */
  default boolean comInt(ArCommands command, int argument) {
    return getPacketSender().comInt(command.getNumber(), argument);
  }

  /** Sends a two-byte command (high, low) now. */
  default boolean com2Bytes(int command, int high, int low) {
    return getPacketSender().com2Bytes(command, high, low);
  }

  /** Sends a two-byte command (high, low) now. */
  default boolean com2Bytes(ArCommands command, int high, int low) {
    return getPacketSender().com2Bytes(command.getNumber(), high, low);
  }

  /** Sends a string command now. */
  default boolean comStr(int command, String argument) {
    return getPacketSender().comStr(command, argument);
  }

  /** Sends a string command now. */
  default boolean comStr(ArCommands command, String argument) {
    return getPacketSender().comStr(command.getNumber(), argument);
  }

  /**
   * Sends a string command with exactly {@code size} bytes now (ARIA's {@code comStrN}): the string
   * is cut or padded with NULs to {@code size}.
   */
  default boolean comStrN(int command, String argument, int size) {
    return getPacketSender().comStrN(command, argument, size);
  }

  /** Sends a string command with exactly {@code size} bytes now. */
  default boolean comStrN(ArCommands command, String argument, int size) {
    return getPacketSender().comStrN(command.getNumber(), argument, size);
  }

  /** Sends a command whose string argument is raw bytes (SAY's note pairs, TTY2 data). */
  default boolean comDataN(ArCommands command, byte[] data) {
    return getPacketSender().comDataN(command.getNumber(), data, 0, data.length);
  }

  /** Sends a packet you built and finalized yourself. */
  default boolean sendPacket(ArRobotPacket packet) {
    return getPacketSender().sendPacket(packet);
  }

  /** Turns the motors on (ENABLE 1). */
  default boolean enableMotors() {
    return getPacketSender().comInt(ArCommands.ENABLE.getNumber(), 1);
  }

  /** Turns the motors off (ENABLE 0). */
  default boolean disableMotors() {
    return getPacketSender().comInt(ArCommands.ENABLE.getNumber(), 0);
  }

  /** Turns all sonar arrays on. */
  default boolean enableSonar() {
    return getPacketSender().comInt(ArCommands.SONAR.getNumber(), 1);
  }

  /** Turns all sonar arrays off. */
  default boolean disableSonar() {
    return getPacketSender().comInt(ArCommands.SONAR.getNumber(), 0);
  }

  /** Asks for a continuous stream of ENCODERpacs. */
  default boolean requestEncoderPackets() {
    return getPacketSender().comInt(ArCommands.ENCODER.getNumber(), 2);
  }

  /** Stops the ENCODERpac stream. */
  default boolean stopEncoderPackets() {
    return getPacketSender().comInt(ArCommands.ENCODER.getNumber(), 0);
  }

  /** Asks for a continuous stream of IOpacs. */
  default boolean requestIOPackets() {
    return getPacketSender().comInt(ArCommands.IOREQUEST.getNumber(), 2);
  }

  /** Stops the IOpac stream. */
  default boolean stopIOPackets() {
    return getPacketSender().comInt(ArCommands.IOREQUEST.getNumber(), 0);
  }
}
