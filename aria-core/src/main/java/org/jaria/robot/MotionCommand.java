package org.jaria.robot;

import org.jaria.protocol.ArCommands;

/**
 * One command that state reflection decided to send: a command and, unless it has none, its integer
 * argument. A plain value, so a test can compare what a cycle sends with what it expects.
 *
 * @param command the command
 * @param hasArgument whether the command carries {@code argument}
 * @param argument the integer argument (VEL2's two bytes packed high first)
 */
record MotionCommand(ArCommands command, boolean hasArgument, int argument) {

  /** A command without argument (PULSE, STOP). */
  static MotionCommand of(ArCommands command) {
    return new MotionCommand(command, false, 0);
  }

  /** A command with an integer argument. */
  static MotionCommand of(ArCommands command, int argument) {
    return new MotionCommand(command, true, argument);
  }

  /** A command whose argument is two signed bytes, high first (VEL2's left and right). */
  static MotionCommand twoBytes(ArCommands command, int high, int low) {
    return new MotionCommand(command, true, ((high & 0xFF) << 8) | (low & 0xFF));
  }

  /** Writes this command through {@code sender}; returns whether it went out. */
  boolean sendWith(ArRobotPacketSender sender) {
    return hasArgument
        ? sender.comInt(command.getNumber(), argument)
        : sender.com(command.getNumber());
  }

  @Override
  public String toString() {
    return hasArgument ? command + " " + argument : command.toString();
  }
}
