package org.jaria.laser;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;

/**
 * Cuts a SCIP 2.0 byte stream into answers (blocks of lines ended by an empty line), however the
 * stream is cut into reads. CR is treated as LF. A block longer than any real answer is dropped and
 * counted, and reading resumes after its end, so memory stays bounded.
 *
 * <p>Not thread-safe: one reader thread feeds it.
 */
public final class ScipReceiver {

  /** Longest line kept (data lines are 65 characters; info lines are short). */
  public static final int MAX_LINE = 256;

  /** Most lines in a block (a full URG-04LX scan is about 40). */
  public static final int MAX_LINES = 200;

  private final DropCounters drops;
  private final StringBuilder line = new StringBuilder();
  private final List<String> lines = new ArrayList<>();
  private boolean overflow;
  private boolean lastWasCr;

  /** A receiver counting dropped blocks in {@code drops}. */
  public ScipReceiver(DropCounters drops) {
    this.drops = drops;
  }

  /** Feeds {@code len} bytes; each complete block goes to {@code out}. */
  public void feed(byte[] b, int off, int len, Consumer<ScipBlock> out) {
    for (int i = off; i < off + len; i++) {
      char c = (char) (b[i] & 0xff);
      if (c == '\n' && lastWasCr) {
        lastWasCr = false;
        continue; // CR LF is one line end
      }
      lastWasCr = c == '\r';
      if (c == '\r' || c == '\n') {
        endLine(out);
      } else if (line.length() < MAX_LINE) {
        line.append(c);
      } else {
        overflow = true;
      }
    }
  }

  private void endLine(Consumer<ScipBlock> out) {
    if (line.length() == 0) {
      if (lines.isEmpty() && !overflow) {
        return; // blank lines between blocks
      }
      if (overflow) {
        drops.drop(DropReason.BAD_LENGTH, "SCIP answer too long");
      } else {
        out.accept(new ScipBlock(lines));
      }
      lines.clear();
      overflow = false;
      return;
    }
    if (lines.size() < MAX_LINES) {
      lines.add(line.toString());
    } else {
      overflow = true;
    }
    line.setLength(0);
  }

  /** Forgets a half-received block (after a reconnect). */
  public void reset() {
    line.setLength(0);
    lines.clear();
    overflow = false;
  }
}
