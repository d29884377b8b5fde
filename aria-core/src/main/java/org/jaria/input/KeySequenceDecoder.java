package org.jaria.input;

import java.util.function.IntConsumer;

/**
 * Turns the characters a terminal sends into {@link ArKeyHandler} key codes: plain characters stay
 * as they are; space, tab, enter and backspace become {@link ArKeyHandler#SPACE} and friends;
 * escape sequences ({@code ESC [ A}, {@code ESC O P}, {@code ESC [ 1 5 ~} ...) become the arrow,
 * function and editing keys. A lone escape is only known to be the Escape key when nothing follows
 * it quickly, so the caller reports a pause with {@link #timeout()}.
 *
 * <p>Garbage is harmless: unknown or over-long sequences are dropped and counted ({@link
 * #getDroppedSequences()}), and decoding carries on with the next character. Not thread-safe: one
 * reader feeds it.
 */
public final class KeySequenceDecoder {

  private static final int MAX_SEQUENCE = 16;

  private enum State {
    IDLE,
    ESC,
    CSI,
    SS3,
    /** Swallowing the rest of an over-long sequence, up to its final byte. */
    SKIP
  }

  private final IntConsumer out;
  private final StringBuilder params = new StringBuilder();
  private State state = State.IDLE;
  private long dropped;

  /** A decoder that hands each decoded key to {@code out}. */
  public KeySequenceDecoder(IntConsumer out) {
    this.out = out;
  }

  /** Feeds one character. */
  public void accept(int ch) {
    switch (state) {
      case IDLE -> plain(ch);
      case ESC -> afterEscape(ch);
      case CSI -> csi(ch);
      case SS3 -> ss3(ch);
      case SKIP -> skip(ch);
    }
  }

  /** Feeds every character of {@code s}. */
  public void accept(CharSequence s) {
    for (int i = 0; i < s.length(); i++) {
      accept(s.charAt(i));
    }
  }

  /**
   * Reports that no character came for a while: a pending lone escape is the Escape key, and an
   * unfinished sequence is dropped.
   */
  public void timeout() {
    if (state == State.ESC) {
      out.accept(ArKeyHandler.ESCAPE);
    } else if (state != State.IDLE && state != State.SKIP) {
      dropped++;
    }
    reset();
  }

  /** Whether the decoder is in the middle of an escape sequence. */
  public boolean isPending() {
    return state != State.IDLE;
  }

  /** Escape sequences dropped because they were unknown, too long or cut short. */
  public long getDroppedSequences() {
    return dropped;
  }

  private void reset() {
    state = State.IDLE;
    params.setLength(0);
  }

  private void plain(int ch) {
    switch (ch) {
      case 0 -> {}
      case 27 -> state = State.ESC;
      case ' ' -> out.accept(ArKeyHandler.SPACE);
      case '\t' -> out.accept(ArKeyHandler.TAB);
      case 10, 13 -> out.accept(ArKeyHandler.ENTER);
      case 8, 127 -> out.accept(ArKeyHandler.BACKSPACE);
      default -> {
        if (ch > 0) {
          out.accept(ch);
        }
      }
    }
  }

  private void afterEscape(int ch) {
    switch (ch) {
      case '[' -> state = State.CSI;
      case 'O' -> state = State.SS3;
      case 27 -> out.accept(ArKeyHandler.ESCAPE); // two escapes: the first was the key
      default -> {
        // Escape then an ordinary key (Alt+key in many terminals): both count.
        out.accept(ArKeyHandler.ESCAPE);
        reset();
        plain(ch);
      }
    }
  }

  private void skip(int ch) {
    if (ch == 27) {
      reset();
      state = State.ESC;
    } else if (ch >= 0x40 && ch <= 0x7E) {
      reset();
    }
  }

  private void ss3(int ch) {
    int key =
        switch (ch) {
          case 'P' -> ArKeyHandler.F1;
          case 'Q' -> ArKeyHandler.F2;
          case 'R' -> ArKeyHandler.F3;
          case 'S' -> ArKeyHandler.F4;
          case 'A' -> ArKeyHandler.UP;
          case 'B' -> ArKeyHandler.DOWN;
          case 'C' -> ArKeyHandler.RIGHT;
          case 'D' -> ArKeyHandler.LEFT;
          case 'H' -> ArKeyHandler.HOME;
          case 'F' -> ArKeyHandler.END;
          default -> -1;
        };
    emitOrDrop(key);
  }

  private void csi(int ch) {
    if ((ch >= '0' && ch <= '9') || ch == ';') {
      if (params.length() >= MAX_SEQUENCE) {
        dropped++;
        params.setLength(0);
        state = State.SKIP;
        return;
      }
      params.append((char) ch);
      return;
    }
    if (ch < 0x40 || ch > 0x7E) {
      // Not a valid final byte: the sequence is broken.
      dropped++;
      reset();
      if (ch == 27) {
        state = State.ESC;
      }
      return;
    }
    int key =
        switch (ch) {
          case 'A' -> ArKeyHandler.UP;
          case 'B' -> ArKeyHandler.DOWN;
          case 'C' -> ArKeyHandler.RIGHT;
          case 'D' -> ArKeyHandler.LEFT;
          case 'H' -> ArKeyHandler.HOME;
          case 'F' -> ArKeyHandler.END;
          case 'P' -> ArKeyHandler.F1;
          case 'Q' -> ArKeyHandler.F2;
          case 'R' -> ArKeyHandler.F3;
          case 'S' -> ArKeyHandler.F4;
          case '~' -> tildeKey(firstParam());
          default -> -1;
        };
    emitOrDrop(key);
  }

  private int firstParam() {
    int end = params.indexOf(";");
    String first = end < 0 ? params.toString() : params.substring(0, end);
    if (first.isEmpty() || first.length() > 3) {
      return -1;
    }
    return Integer.parseInt(first);
  }

  private static int tildeKey(int n) {
    return switch (n) {
      case 1, 7 -> ArKeyHandler.HOME;
      case 2 -> ArKeyHandler.INSERT;
      case 3 -> ArKeyHandler.DEL;
      case 4, 8 -> ArKeyHandler.END;
      case 5 -> ArKeyHandler.PAGEUP;
      case 6 -> ArKeyHandler.PAGEDOWN;
      case 11 -> ArKeyHandler.F1;
      case 12 -> ArKeyHandler.F2;
      case 13 -> ArKeyHandler.F3;
      case 14 -> ArKeyHandler.F4;
      case 15 -> ArKeyHandler.F5;
      case 17 -> ArKeyHandler.F6;
      case 18 -> ArKeyHandler.F7;
      case 19 -> ArKeyHandler.F8;
      case 20 -> ArKeyHandler.F9;
      case 21 -> ArKeyHandler.F10;
      case 23 -> ArKeyHandler.F11;
      case 24 -> ArKeyHandler.F12;
      default -> -1;
    };
  }

  private void emitOrDrop(int key) {
    if (key < 0) {
      dropped++;
    } else {
      out.accept(key);
    }
    reset();
  }
}
