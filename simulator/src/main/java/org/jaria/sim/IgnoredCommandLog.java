package org.jaria.sim;

import java.util.ArrayList;
import java.util.List;
import org.jaria.protocol.ArCommands;
import org.jaria.sim.server.IgnoredCommand;

/**
 * Counts the commands a world's robots did not carry out, by number and reason. Used under the
 * world's lock only.
 */
final class IgnoredCommandLog {

  private static final IgnoredCommand.Reason[] REASONS = IgnoredCommand.Reason.values();

  private final long[][] counts = new long[256][REASONS.length];

  /**
   * Counts one; returns whether it is the first of its number and reason (the one to log).
   *
   * @throws IllegalArgumentException if {@code command} is not a command number (0..255)
   */
  boolean record(int command, IgnoredCommand.Reason reason) {
    if (command < 0 || command > 255) {
      throw new IllegalArgumentException("command numbers are 0..255, got " + command);
    }
    return counts[command][reason.ordinal()]++ == 0;
  }

  /** Every command ignored so far, by number, then reason. */
  List<IgnoredCommand> snapshot() {
    List<IgnoredCommand> out = new ArrayList<>();
    for (int c = 0; c < counts.length; c++) {
      for (IgnoredCommand.Reason r : REASONS) {
        long n = counts[c][r.ordinal()];
        if (n > 0) {
          ArCommands known = ArCommands.fromNumber(c);
          out.add(new IgnoredCommand(c, known == null ? "unknown" : known.name(), r, n));
        }
      }
    }
    return out;
  }
}
