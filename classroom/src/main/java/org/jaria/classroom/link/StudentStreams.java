package org.jaria.classroom.link;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.InputStream;
import java.io.OutputStream;

/**
 * The grader's end of the byte streams to one student's process (its standard output and input),
 * over which {@link StudentLink} runs.
 *
 * @param in what the student's side sends
 * @param out what the grader sends
 */
public record StudentStreams(DataInputStream in, DataOutputStream out) {

  /** Streams over a process's (or a pipe's) raw streams. */
  public static StudentStreams of(InputStream in, OutputStream out) {
    return new StudentStreams(
        new DataInputStream(new BufferedInputStream(in, 1 << 16)),
        new DataOutputStream(new BufferedOutputStream(out, 1 << 16)));
  }
}
