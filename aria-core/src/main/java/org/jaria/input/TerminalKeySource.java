package org.jaria.input;

import java.io.IOException;
import org.jline.terminal.Attributes;
import org.jline.terminal.Terminal;
import org.jline.terminal.TerminalBuilder;
import org.jline.utils.NonBlockingReader;

/**
 * Keys from the terminal the program runs in, through JLine: the terminal is put in raw mode (no
 * echo, no line buffering, so each key press arrives at once) and restored by {@link #close()}.
 * When the program does not run in a real terminal, JLine falls back to a "dumb" terminal and keys
 * arrive when Enter is pressed.
 */
public final class TerminalKeySource implements KeySource {

  private final Terminal terminal;
  private final Attributes saved;
  private final NonBlockingReader reader;
  private boolean closed;

  /**
   * Opens the system terminal in raw mode.
   *
   * @throws IOException if the terminal cannot be opened
   */
  public TerminalKeySource() throws IOException {
    terminal = TerminalBuilder.builder().system(true).name("jaria-keys").build();
    saved = terminal.enterRawMode();
    reader = terminal.reader();
  }

  @Override
  public int read(long timeoutMs) throws IOException {
    int c = reader.read(timeoutMs);
    if (c == NonBlockingReader.READ_EXPIRED) {
      return TIMEOUT;
    }
    return c < 0 ? EOF : c;
  }

  @Override
  public synchronized void close() throws IOException {
    if (closed) {
      return;
    }
    closed = true;
    try {
      terminal.setAttributes(saved);
    } finally {
      terminal.close();
    }
  }
}
