package org.jaria.classroom.sandbox;

import java.time.Duration;

/**
 * What one student's JVM may use.
 *
 * @param heapMb the Java heap, MB
 * @param tasks the processes and threads its user may have at once (the JVM itself needs about 30)
 * @param cpu processor time, summed over its threads
 * @param fileBytes the largest file it may write (its output log included)
 * @param files the most files and folders its scratch folder may hold (its copied sources and
 *     compiled classes included)
 */
public record Limits(int heapMb, int tasks, Duration cpu, long fileBytes, int files) {

  /** The most files and folders a scratch folder may hold, unless a test says otherwise. */
  public static final int FILES = 1000;

  /** Limits for a grading with {@code timeout} of real time per student. */
  public static Limits forTimeout(Duration timeout) {
    return new Limits(256, 128, timeout.multipliedBy(2).plusSeconds(10), 32L << 20, FILES);
  }

  /** The JVM options that apply the limits the JVM itself enforces. */
  public java.util.List<String> jvmOptions() {
    return java.util.List.of(
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
