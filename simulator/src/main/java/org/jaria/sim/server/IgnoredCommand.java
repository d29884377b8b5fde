package org.jaria.sim.server;

/**
 * A client command the simulator received but did not carry out, with how often it came. A teacher
 * or a test can read these from {@code SimWorld.getIgnoredCommands()} to see what a program asked
 * for that the simulated robot could not do. Each kind is logged once.
 *
 * @param command the command number
 * @param name the command's ARCOS name, or "unknown"
 * @param reason why it was not carried out
 * @param count how many times it arrived
 */
public record IgnoredCommand(int command, String name, Reason reason, long count) {

  /** Why a command was not carried out. */
  public enum Reason {
    /** ARCOS has no command with this number (the robot ignores it too). */
    UNKNOWN,
    /** A real ARCOS command that this simulator does not simulate (arm, pan-tilt, ...). */
    NOT_SIMULATED,
    /** The command is for a device this simulated robot does not carry (laser, gyro ...). */
    NO_DEVICE,
    /** The user told the simulator to ignore this command ({@code --ignore-command}). */
    BY_OPTION,
    /**
     * MobileSim does not answer this request (encoder, I/O, joystick, compass and gripper packets),
     * so neither does the {@code mobilesim} profile.
     */
    NOT_IN_MOBILESIM,
    /**
     * Only clients on the simulator's own machine may send it (SIM_EXIT, map loads without a map
     * folder); this client is on another machine.
     */
    REMOTE_CLIENT
  }
}
