package org.jaria.input;

import java.io.IOException;

/**
 * Where an {@link ArKeyHandler}'s reader thread gets characters from: a terminal in raw mode
 * ({@link TerminalKeySource}), or anything else that produces characters one at a time.
 */
public interface KeySource extends AutoCloseable {

  /** Returned by {@link #read} when nothing arrived in time. */
  int TIMEOUT = -2;

  /** Returned by {@link #read} when the source has ended. */
  int EOF = -1;

  /**
   * Waits up to {@code timeoutMs} for the next character.
   *
   * @return the character's code, {@link #TIMEOUT} or {@link #EOF}
   * @throws IOException if reading failed
   */
  int read(long timeoutMs) throws IOException;

  /** Releases the source (a terminal gets its previous settings back). */
  @Override
  void close() throws IOException;
}
