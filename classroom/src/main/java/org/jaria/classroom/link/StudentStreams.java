package org.jaria.classroom.link;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.Objects;

/**
 * The grader's end of the byte streams to one student's process (its standard output and input),
 * over which {@link StudentLink} runs, and the audit the link keeps of what it refused.
 *
 * @param in what the student's side sends
 * @param out what the grader sends
 * @param audit what the link dropped and whether the robot's path jumped, for the grader
 */
public record StudentStreams(DataInputStream in, DataOutputStream out, LinkAudit audit) {

  /** Checks. */
  public StudentStreams {
    Objects.requireNonNull(in, "in");
    Objects.requireNonNull(out, "out");
    Objects.requireNonNull(audit, "audit");
  }

  /** Streams with a fresh audit. */
  public StudentStreams(DataInputStream in, DataOutputStream out) {
    this(in, out, new LinkAudit());
  }

  /** Streams over a process's (or a pipe's) raw streams, with a fresh audit. */
  public static StudentStreams of(InputStream in, OutputStream out) {
    return new StudentStreams(
        new DataInputStream(new BufferedInputStream(in, 1 << 16)),
        new DataOutputStream(new BufferedOutputStream(out, 1 << 16)));
  }
}
