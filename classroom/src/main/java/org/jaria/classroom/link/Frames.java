package org.jaria.classroom.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;

/**
 * The link's frames: one type byte, then the frame's fields. The grader sends a frame and reads
 * exactly one answer; the student's side answers each frame before it reads the next. Lengths are
 * bounded so that a broken or hostile peer gives a clear error, never a huge allocation.
 *
 * <p>Both ends speak them: {@link StudentLink} here, in the grader, and the student's side ({@code
 * org.jaria.classroom.grading.StudentHarness}), which runs the assignment's half in the student's
 * JVM and so lives with the assignments' API it calls.
 */
public final class Frames {

  /** Grader: hello (robot name, channel names); answer {@link #REPLY}. */
  public static final int HELLO = 'H';

  /** Grader: one tick (time, bytes per channel); answer {@link #STATE}. */
  public static final int TICK = 'T';

  /** Grader: make the student's object and hook it up; answer {@link #REPLY}. */
  public static final int SET_UP = 'U';

  /** Grader: a named question or step for the assignment's student side; answer {@link #REPLY}. */
  public static final int CALL = 'C';

  /** Grader: start the program; answer {@link #STATE} once it first waits or ends. */
  public static final int PROGRAM = 'P';

  /** Grader: stop the program; answer {@link #REPLY}. */
  public static final int STOP = 'Q';

  /** Grader: the end; answer {@link #BYE}. */
  public static final int END = 'E';

  /** Student: what came of compiling the submission (its first frame; see CompileReport). */
  public static final int COMPILED = 'K';

  /** Student: an answer with one string. */
  public static final int REPLY = 'R';

  /** Student: the state after a tick (program state, robot flags, message, bytes per channel). */
  public static final int STATE = 'S';

  /** Student: done, about to end normally. */
  public static final int BYE = 'B';

  /** Student: the JVM is shutting down (System.exit) outside the grader's END. */
  public static final int EXITING = 'X';

  /** The most bytes one channel carries in one frame. */
  public static final int MAX_BYTES = 4 << 20;

  /** The most characters in a string field. */
  public static final int MAX_STRING = 256 << 10;

  /** The most channels. */
  public static final int MAX_CHANNELS = 8;

  private Frames() {}

  public static void writeBytes(DataOutputStream out, byte[] b, int len) throws IOException {
    out.writeInt(len);
    out.write(b, 0, len);
  }

  public static byte[] readBytes(DataInputStream in) throws IOException {
    int n = in.readInt();
    if (n < 0 || n > MAX_BYTES) {
      throw new IOException("bad frame: " + n + " bytes in one channel");
    }
    byte[] b = new byte[n];
    in.readFully(b);
    return b;
  }

  public static void writeString(DataOutputStream out, String s) throws IOException {
    String t = s.length() > MAX_STRING ? s.substring(0, MAX_STRING) : s;
    byte[] b = t.getBytes(java.nio.charset.StandardCharsets.UTF_8);
    writeBytes(out, b, b.length);
  }

  public static String readString(DataInputStream in) throws IOException {
    byte[] b = readBytes(in);
    if (b.length > 4 * MAX_STRING) {
      throw new IOException("bad frame: a string of " + b.length + " bytes");
    }
    return new String(b, java.nio.charset.StandardCharsets.UTF_8);
  }
}
