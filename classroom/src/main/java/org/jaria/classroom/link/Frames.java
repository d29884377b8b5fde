package org.jaria.classroom.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;

/**
 * The link's frames: one type byte, then the frame's fields. The grader sends a frame and reads
 * exactly one answer; the student's side answers each frame before it reads the next. Lengths are
 * bounded so that a broken or hostile peer gives a clear error, never a huge allocation.
 */
final class Frames {

  /** Grader: hello (robot name, channel names); answer {@link #REPLY}. */
  static final int HELLO = 'H';

  /** Grader: one tick (time, bytes per channel); answer {@link #STATE}. */
  static final int TICK = 'T';

  /** Grader: make the student's object and hook it up; answer {@link #REPLY}. */
  static final int SET_UP = 'U';

  /** Grader: a named question or step for the assignment's student side; answer {@link #REPLY}. */
  static final int CALL = 'C';

  /** Grader: start the program; answer {@link #STATE} once it first waits or ends. */
  static final int PROGRAM = 'P';

  /** Grader: stop the program; answer {@link #REPLY}. */
  static final int STOP = 'Q';

  /** Grader: the end; answer {@link #BYE}. */
  static final int END = 'E';

  /** Student: what came of compiling the submission (its first frame; see CompileReport). */
  static final int COMPILED = 'K';

  /** Student: an answer with one string. */
  static final int REPLY = 'R';

  /** Student: the state after a tick (program state, robot flags, message, bytes per channel). */
  static final int STATE = 'S';

  /** Student: done, about to end normally. */
  static final int BYE = 'B';

  /** Student: the JVM is shutting down (System.exit) outside the grader's END. */
  static final int EXITING = 'X';

  /** The most bytes one channel carries in one frame. */
  static final int MAX_BYTES = 4 << 20;

  /** The most characters in a string field. */
  static final int MAX_STRING = 256 << 10;

  /** The most channels. */
  static final int MAX_CHANNELS = 8;

  private Frames() {}

  static void writeBytes(DataOutputStream out, byte[] b, int len) throws IOException {
    out.writeInt(len);
    out.write(b, 0, len);
  }

  static byte[] readBytes(DataInputStream in) throws IOException {
    int n = in.readInt();
    if (n < 0 || n > MAX_BYTES) {
      throw new IOException("bad frame: " + n + " bytes in one channel");
    }
    byte[] b = new byte[n];
    in.readFully(b);
    return b;
  }

  static void writeString(DataOutputStream out, String s) throws IOException {
    String t = s.length() > MAX_STRING ? s.substring(0, MAX_STRING) : s;
    byte[] b = t.getBytes(java.nio.charset.StandardCharsets.UTF_8);
    writeBytes(out, b, b.length);
  }

  static String readString(DataInputStream in) throws IOException {
    byte[] b = readBytes(in);
    if (b.length > 4 * MAX_STRING) {
      throw new IOException("bad frame: a string of " + b.length + " bytes");
    }
    return new String(b, java.nio.charset.StandardCharsets.UTF_8);
  }
}
