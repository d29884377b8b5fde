package org.jaria.sim.server;

import java.util.Set;
import org.jaria.protocol.ArCommands;

/**
 * Which client commands a robot carries out, as a plain decision over values: the numbers the user
 * chose to ignore (MobileSim's {@code --ignore-command}) are ignored for everyone; SIM_EXIT from
 * another machine only if {@code remoteExit}; client map loads (SIM_CTRL 1 and 2) from another
 * machine only if {@code remoteMapLoads} (the user named a map folder).
 *
 * @param ignored command numbers ignored for every client
 * @param remoteExit whether a client on another machine may end the simulator
 * @param remoteMapLoads whether a client on another machine may load maps
 */
public record CommandPolicy(Set<Integer> ignored, boolean remoteExit, boolean remoteMapLoads) {

  /** SIM_CTRL operations that load a map. */
  private static final int LOAD_MAP = 1;

  private static final int MASTER_LOAD_MAP = 2;

  /** Carries out everything for everyone except SIM_EXIT and map loads from other machines. */
  public static final CommandPolicy DEFAULT = new CommandPolicy(Set.of(), false, false);

  /** Copies the set. */
  public CommandPolicy {
    ignored = Set.copyOf(ignored);
  }

  /**
   * Why command {@code command} from a client of kind {@code kind} is not carried out, or {@code
   * null} if it is.
   *
   * @param simCtrlOp the operation code of a SIM_CTRL command (any value for other commands)
   */
  public IgnoredCommand.Reason refusal(int command, int simCtrlOp, ClientKind kind) {
    if (ignored.contains(command)) {
      return IgnoredCommand.Reason.BY_OPTION;
    }
    if (kind.isLocal()) {
      return null;
    }
    if (command == ArCommands.SIM_EXIT.getNumber() && !remoteExit) {
      return IgnoredCommand.Reason.REMOTE_CLIENT;
    }
    if (command == ArCommands.SIM_CTRL.getNumber()
        && (simCtrlOp == LOAD_MAP || simCtrlOp == MASTER_LOAD_MAP)
        && !remoteMapLoads) {
      return IgnoredCommand.Reason.REMOTE_CLIENT;
    }
    return null;
  }

  /** Whether SIM_CTRL operation {@code op} loads a map. */
  public static boolean isMapLoad(int op) {
    return op == LOAD_MAP || op == MASTER_LOAD_MAP;
  }
}
