package org.jaria.classroom.sandbox;

import java.time.Duration;
import java.util.List;

/**
 * What one student's JVM may use, while it compiles their code and while it runs it.
 *
 * @param heapMb the Java heap, MB
 * @param tasks the processes and threads its user may have at once (the JVM itself needs about 30)
 * @param cpu processor time, summed over its threads
 * @param fileBytes the largest file it may write
 * @param files the most files and folders its scratch folder may hold (its copied sources and
 *     compiled classes included)
 * @param scratchBytes the most bytes all the files of its scratch folder may hold together
 * @param outputBytes how much of its output (standard error) the grader keeps
 */
public record Limits(
    int heapMb,
    int tasks,
    Duration cpu,
    long fileBytes,
    int files,
    long scratchBytes,
    long outputBytes) {

  /** The most files and folders a scratch folder may hold, unless a test says otherwise. */
  public static final int FILES = 1000;

  /** The most bytes a scratch folder may hold, unless a test says otherwise. */
  public static final long SCRATCH_BYTES = 64L << 20;

  /** Limits for a grading with {@code timeout} of real time per student. */
  public static Limits forTimeout(Duration timeout) {
    return new Limits(
        256,
        128,
        timeout.multipliedBy(2).plusSeconds(10),
        16L << 20,
        FILES,
        SCRATCH_BYTES,
        1L << 20);
  }

  /** The JVM options that apply the limits the JVM itself enforces. */
  public List<String> jvmOptions() {
    return List.of(
        "-Xmx" + heapMb + "m",
        "-Xss1m",
        "-XX:MaxMetaspaceSize=128m",
        "-XX:MaxDirectMemorySize=64m",
        "-XX:+UseSerialGC",
        "-XX:TieredStopAtLevel=1",
        "-XX:CICompilerCount=1",
        "-XX:+ExitOnOutOfMemoryError",
        "-XX:-UsePerfData",
        "-XX:+DisableAttachMechanism",
        "-Djava.awt.headless=true",
        "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn");
  }
}
