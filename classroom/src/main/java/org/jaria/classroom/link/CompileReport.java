package org.jaria.classroom.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;

/**
 * What came of compiling a submission inside the student's own (sandboxed, limited) JVM: the first
 * frame that JVM sends, before any of the student's code has been loaded, so the grader can trust
 * it. Compiling there puts the compiler under the same time, memory and process limits as the run:
 * a source that makes the compiler work for minutes or eat gigabytes costs only its own student.
 *
 * @param outcome {@link #COMPILED}, {@link #ERRORS} or {@link #COMPILER_FAILED}
 * @param text the compile errors, or what stopped the compiler (empty when compiled)
 */
public record CompileReport(int outcome, String text) {

  /** The classes are compiled; the link follows. */
  public static final int COMPILED = 0;

  /** The code does not compile: {@code text} holds the errors. */
  public static final int ERRORS = 1;

  /** The compiler itself gave up (ran out of stack, say): {@code text} says how. */
  public static final int COMPILER_FAILED = 2;

  /** Sends this report as the link's first frame. */
  public void write(DataOutputStream out) throws IOException {
    out.writeByte(Frames.COMPILED);
    out.writeByte(outcome);
    Frames.writeString(out, text);
    out.flush();
  }

  /**
   * Reads the report a student's JVM sends first.
   *
   * @throws IOException if the JVM ended (or was stopped) before it could say, or sent something
   *     else
   */
  public static CompileReport read(DataInputStream in) throws IOException {
    int t = in.read();
    if (t < 0) {
      throw new EOFException("the student's JVM ended while compiling");
    }
    if (t != Frames.COMPILED) {
      throw new IOException("the student's JVM sent frame " + t + " before its compile report");
    }
    int outcome = in.readUnsignedByte();
    if (outcome > COMPILER_FAILED) {
      throw new IOException("not a compile outcome: " + outcome);
    }
    return new CompileReport(outcome, Frames.readString(in));
  }
}
