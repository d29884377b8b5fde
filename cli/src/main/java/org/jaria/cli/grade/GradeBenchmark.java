package org.jaria.cli.grade;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.classgrading.GradeRequest;
import org.jaria.classroom.sandbox.Sandbox;

/**
 * {@code jaria bench grade}: grades a made-up class of square submissions (good ones, unchanged
 * starters, some that do not compile, some that hang, some that busy-wait) with two jobs and with
 * one, times both, and checks the gradebook and every grade file are the same; the load of the
 * machine is printed beside the times, since they depend on it.
 */
public final class GradeBenchmark {

  /**
   * How many submissions of each kind a class has.
   *
   * @param good reference solutions
   * @param starters unchanged starter files
   * @param broken that do not compile
   * @param hanging that loop forever in their constructor
   * @param busy that busy-wait without the robot's clock
   */
  record Mix(int good, int starters, int broken, int hanging, int busy) {

    int total() {
      return good + starters + broken + hanging + busy;
    }
  }

  /** The class of the issue: 60 submissions. */
  static final Mix FULL = new Mix(30, 12, 5, 5, 8);

  /** A class small enough to try the benchmark in a minute. */
  static final Mix QUICK = new Mix(4, 2, 1, 1, 2);

  static final Duration TIMEOUT = Duration.ofSeconds(10);

  private GradeBenchmark() {}

  /** Runs the benchmark on the full class (or the quick one) and returns its table. */
  public static String run(boolean quick) throws IOException {
    Mix mix = quick ? QUICK : FULL;
    Path root = Files.createTempDirectory("jaria-bench-grade-");
    try {
      Path subs = root.resolve("subs");
      writeClass(subs, mix, kit("solution"), kit("starter"));
      boolean isolated = Sandbox.whyUnavailable().isEmpty();
      double loadBefore = load();
      StringBuilder t = new StringBuilder();
      t.append(
          String.format(
              Locale.ROOT,
              "jaria bench grade: %d square submissions (%d good, %d starters, %d that do not"
                  + " compile, %d that hang, %d busy-waiting), timeout %d s, %s%n",
              mix.total(),
              mix.good(),
              mix.starters(),
              mix.broken(),
              mix.hanging(),
              mix.busy(),
              TIMEOUT.toSeconds(),
              isolated
                  ? "each in a sandbox"
                  : "WITHOUT a sandbox (bubblewrap is not usable here)"));
      t.append(
          String.format(
              Locale.ROOT,
              "%d cores, load average %.1f before%n%n",
              Runtime.getRuntime().availableProcessors(),
              loadBefore));
      t.append(
          String.format(Locale.ROOT, "%-6s %12s %20s%n", "jobs", "wall time", "load avg after"));
      double[] seconds = new double[3];
      for (int jobs : new int[] {2, 1}) {
        seconds[jobs] =
            grade(subs, root.resolve("out" + jobs), root.resolve("scratch"), jobs, !isolated);
        t.append(String.format(Locale.ROOT, "%-6d %10.1f s %20.1f%n", jobs, seconds[jobs], load()));
      }
      List<String> differ = differences(root.resolve("out1"), root.resolve("out2"));
      t.append('\n')
          .append(
              differ.isEmpty()
                  ? "gradebook.csv and every grade.txt: identical for --jobs 1 and --jobs 2"
                  : "DIFFERENT for --jobs 1 and --jobs 2: " + differ)
          .append('\n');
      return t.toString();
    } finally {
      deleteTree(root);
    }
  }

  private static double grade(Path subs, Path out, Path scratch, int jobs, boolean unsafe)
      throws IOException {
    GradeRequest r =
        GradeRequest.of("square", subs, out)
            .withJobs(jobs)
            .withTimeout(TIMEOUT)
            .withScratchRoot(scratch);
    if (unsafe) {
      r = r.withoutIsolation();
    }
    StringWriter sink = new StringWriter();
    long t0 = System.nanoTime();
    int exit = ClassGrading.grade(r, new PrintWriter(sink), new PrintWriter(sink));
    double s = (System.nanoTime() - t0) / 1e9;
    if (exit != ClassGrading.GRADED) {
      throw new IllegalStateException("grading failed: " + sink);
    }
    return s;
  }

  /** The class: {@code mix} of submissions in folders named after their kind. */
  static void writeClass(Path subs, Mix mix, String solution, String starter) throws IOException {
    put(subs, "good", mix.good(), solution);
    put(subs, "bad", mix.starters(), starter);
    put(subs, "broken", mix.broken(), solution.replaceFirst(";", ""));
    put(subs, "hangctor", mix.hanging(), HANGING);
    put(subs, "busywait", mix.busy(), BUSY);
  }

  /** Loops forever in its constructor. */
  private static final String HANGING =
      """
      import org.jaria.classroom.RobotProgram;
      import org.jaria.robot.ArRobot;
      public class Square implements RobotProgram {
        private long n;
        public Square() { while (n >= 0) { n++; } }
        public void run(ArRobot robot) {}
      }
      """;

  /** Waits for the move without the robot's clock. */
  private static final String BUSY =
      """
      import org.jaria.classroom.RobotProgram;
      import org.jaria.robot.ArRobot;
      public class Square implements RobotProgram {
        public void run(ArRobot robot) {
          robot.enableMotors();
          robot.move(2000);
          while (!robot.isMoveDone()) {
            if (Thread.currentThread().isInterrupted()) return;
          }
        }
      }
      """;

  private static void put(Path subs, String kind, int n, String source) throws IOException {
    for (int i = 1; i <= n; i++) {
      Path d = subs.resolve(String.format(Locale.ROOT, "%s%02d", kind, i));
      Files.createDirectories(d);
      Files.writeString(d.resolve("Square.java"), source, StandardCharsets.UTF_8);
    }
  }

  /** The files of the gradebook that differ between two report folders (empty: none). */
  static List<String> differences(Path a, Path b) throws IOException {
    Map<String, byte[]> fa = gradeFiles(a);
    Map<String, byte[]> fb = gradeFiles(b);
    List<String> out = new ArrayList<>();
    if (!fa.keySet().equals(fb.keySet())) {
      out.add("files " + fa.keySet() + " vs " + fb.keySet());
      return out;
    }
    for (String k : fa.keySet()) {
      if (!java.util.Arrays.equals(fa.get(k), fb.get(k))) {
        out.add(k);
      }
    }
    return out;
  }

  private static Map<String, byte[]> gradeFiles(Path out) throws IOException {
    Map<String, byte[]> m = new TreeMap<>();
    m.put("gradebook.csv", Files.readAllBytes(out.resolve("gradebook.csv")));
    try (Stream<Path> s = Files.walk(out.resolve("students"))) {
      for (Path p : s.filter(f -> f.getFileName().toString().equals("grade.txt")).toList()) {
        m.put(out.relativize(p).toString(), Files.readAllBytes(p));
      }
    }
    return m;
  }

  private static String kit(String which) throws IOException {
    for (Path base : List.of(Path.of("classroom"), Path.of("..", "classroom"))) {
      Path p = base.resolve("assignments/square").resolve(which).resolve("Square.java");
      if (Files.isRegularFile(p)) {
        return Files.readString(p, StandardCharsets.UTF_8);
      }
    }
    throw new IOException(
        "classroom/assignments/square is not here: run jaria bench grade from JAria's folder");
  }

  private static double load() {
    return ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
  }

  private static void deleteTree(Path p) throws IOException {
    org.jaria.classroom.sandbox.Cleanup.deleteTree(p);
  }
}
