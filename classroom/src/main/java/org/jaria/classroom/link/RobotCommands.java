package org.jaria.classroom.link;

import org.jaria.protocol.ArCommands;

/**
 * What a real Pioneer accepts from its client, as a plain decision over command numbers: the ARCOS
 * commands of a robot (the handshake, motion, sonar, I/O, the AUX ports...), and nothing that only
 * a simulator understands. MobileSim's SIM_* commands (set the robot's true pose, reset it, load a
 * map, end the simulator, configure a simulated laser) move or change the world without driving, so
 * a student's link never carries them to the grading world; numbers ARCOS does not know are not
 * carried either.
 */
public final class RobotCommands {

  private RobotCommands() {}

  /** Whether a real robot's ARCOS takes command {@code number} from its client. */
  public static boolean accepted(int number) {
    ArCommands c = ArCommands.fromNumber(number);
    return c != null && !simulatorOnly(c);
  }

  /** Whether {@code c} is a command only a simulator understands (MobileSim's SIM_* family). */
  public static boolean simulatorOnly(ArCommands c) {
    return c.name().startsWith("SIM_");
  }

  /** How a dropped command is named in a report: its ARCOS name, or its number if it has none. */
  public static String name(int number) {
    ArCommands c = ArCommands.fromNumber(number);
    return c != null ? c.name() : "command " + number;
  }
}
