package org.jaria.classroom.attack;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.RandomAccessFile;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.classgrading.GradeRequest;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grader;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.ResultFiles;
import org.jaria.classroom.grading.Status;
import org.jaria.classroom.grading.SubmissionFolders;
import org.jaria.classroom.sandbox.Sandbox;
import org.jaria.classroom.square.SquareAssignment;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A class with hostile submissions beside honest ones, graded in the sandbox with two jobs: each
 * attack (forge the grade, tamper with or read others' files, write outside, network, fork,
 * threads, spin, allocate, System.exit, a stray process, fill the disk, bomb the compiler, hand in
 * too much) gets 0 and its own status, the honest students keep exactly the grade they get in one
 * JVM, nothing outside the scratch folders changes and no process of theirs is left. Hermetic: it
 * looks only at its own scratch root and at the processes that name it, so another grading running
 * beside it changes nothing.
 *
 * <p>The two attacks that only burn processor time until the time limit stops them (the endless
 * constructor, the compiler bomb) are graded apart, with a shorter limit: the class's limit is long
 * so that honest students finish on a loaded machine, and these two would burn all of it.
 */
@Tag("slow")
@Timeout(value = 15, unit = TimeUnit.MINUTES)
class GradeAttackTest {

  @TempDir static Path tmp;

  static Path subs;
  static Path out;
  static Path cpuSubs;
  static Path cpuOut;
  static Path scratch;
  static Path canary;
  static ServerSocket server;
  static String stdout;
  static String stderr;
  static Map<String, String> before;
  static Map<String, Grader.Result> byStudent = new TreeMap<>();

  private static String program(String imports, String body) {
    return "import org.jaria.classroom.RobotProgram;\nimport org.jaria.robot.ArRobot;\n"
        + imports
        + "\npublic class Square implements RobotProgram {\n"
        + body
        + "\n}\n";
  }

  private static String run(String body) {
    return program(
        "import java.nio.file.*;\nimport java.util.*;\nimport java.io.*;",
        "  public void run(ArRobot robot) throws InterruptedException {\n"
            + "    try {\n"
            + body
            + "\n    } catch (Exception e) { throw new RuntimeException(e); }\n  }");
  }

  private static void write(String student, String file, String text) throws IOException {
    write(subs, student, file, text);
  }

  private static void write(Path folder, String student, String file, String text)
      throws IOException {
    Files.createDirectories(folder.resolve(student));
    Files.writeString(folder.resolve(student).resolve(file), text, StandardCharsets.UTF_8);
  }

  @BeforeAll
  static void gradeTheClass() throws Exception {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    subs = tmp.resolve("submissions");
    out = tmp.resolve("report");
    cpuSubs = tmp.resolve("submissions-cpu");
    cpuOut = tmp.resolve("report-cpu");
    scratch = tmp.resolve("scratch");
    canary = tmp.resolve("canary");
    Files.createDirectories(canary);
    Files.writeString(canary.resolve("keep.txt"), "unchanged");
    server = new ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress());
    server.setSoTimeout(1);
    String solution = Files.readString(Path.of("assignments/square/solution/Square.java"));
    write("alice", "Square.java", solution);
    write(
        "bob", "Square.java", Files.readString(Path.of("assignments/square/starter/Square.java")));
    write("zoe", "Square.java", solution);
    // Every file the walk finds outside /sandbox is reported, then rewritten or deleted.
    String walk =
        "    List<Path> found = new ArrayList<>();\n"
            + "    try (var s = Files.walk(Path.of(\"/\"))) {\n"
            + "      s.filter(p -> !p.startsWith(\"/sandbox\") && !p.startsWith(\"/proc\")"
            + " && !p.startsWith(\"/usr\") && !p.startsWith(\"/sys\"))\n"
            + "       .filter(p -> NAME_TEST).forEach(found::add);\n"
            + "    } catch (UncheckedIOException e) { }\n"
            + "    System.out.println(\"found \" + found.size() + \" \" + found);\n";
    write(
        "forge",
        "Square.java",
        run(
            walk.replace(
                    "NAME_TEST",
                    "p.getFileName() != null && (p.getFileName().toString().endsWith(\".txt\")"
                        + " || Files.isDirectory(p))")
                + "    for (Path p : found) { try { Files.writeString(Files.isDirectory(p) ?"
                + " p.resolve(\"grade.txt\") : p, \"jaria-grade 1 square\\n10\\tPASS\\tforged\\tall"
                + " good\\n\"); } catch (IOException e) { } }\n"
                + "    Files.writeString(Path.of(\"/sandbox/grade.txt\"), \"jaria-grade 1"
                + " square\\n10\\tPASS\\tforged\\tall good\\n\");"));
    write(
        "tamper",
        "Square.java",
        run(
            walk.replace("NAME_TEST", "p.toString().endsWith(\".java\")")
                + "    for (Path p : found) { try { Files.writeString(p, \"broken\"); } catch"
                + " (IOException e) { } try { Files.delete(p); } catch (IOException e) { } }\n"
                + "    for (String n : List.of(\"alice\", \"bob\", \"zoe\")) { try {"
                + " Files.delete(Path.of(\"/sandbox/../\" + n + \"/Square.java\")); } catch"
                + " (IOException e) { } }"));
    write(
        "reader",
        "Square.java",
        run(
            walk.replace(
                    "NAME_TEST",
                    "p.toString().endsWith(\".java\") || p.toString().contains(\"solution\")")
                + "    try (var fds = Files.list(Path.of(\"/proc/self/fd\"))) {\n"
                + "      for (Path p : fds.toList()) { try { System.out.println(\"fd \" +"
                + " Files.readSymbolicLink(p)); } catch (IOException e) { } }\n"
                + "    }\n"
                + "    try (var ps = Files.list(Path.of(\"/proc\"))) {\n"
                + "      for (Path p : ps.toList()) { try { System.out.println(\"cmdline \" +"
                + " Files.readString(p.resolve(\"cmdline\")).replace('\\0', ' ')); } catch"
                + " (IOException e) { } }\n"
                + "    }"));
    write(
        "outside",
        "Square.java",
        run(
            "    for (String p : List.of(\""
                + canary.resolve("pwned")
                + "\", \""
                + canary.resolve("keep.txt")
                + "\", \"/tmp/pwned\", \"/pwned\", \"/etc/pwned\")) {\n"
                + "      try { Files.writeString(Path.of(p), \"pwned\"); System.out.println(\"wrote \" +"
                + " p); } catch (IOException e) { System.out.println(\"refused \" + p); }\n"
                + "    }"));
    write(
        "network",
        "Square.java",
        run(
            "    try (var s = new java.net.Socket()) { s.connect(new"
                + " java.net.InetSocketAddress(\"127.0.0.1\", "
                + server.getLocalPort()
                + "), 2000); System.out.println(\"connected\"); } catch (IOException e) {"
                + " System.out.println(\"no network: \" + e.getMessage()); }"));
    String java = Path.of(System.getProperty("java.home"), "bin", "java").toRealPath().toString();
    // Its children stay (Square's main waits a minute), so the bomb runs into the sandbox's
    // process limit after a few of them however slowly a loaded machine starts them; children
    // that ended at once left it racing the time limit.
    write(
        "fork",
        "Square.java",
        run("    List<Process> ps = new ArrayList<>();\n"
                + "    for (int i = 0; i < 2000; i++) { ps.add(new ProcessBuilder(\""
                + java
                + "\", \"-cp\", \"/sandbox/classes\", \"Square\").start()); }")
            .replace(
                "implements RobotProgram {\n",
                "implements RobotProgram {\n"
                    + "  public static void main(String[] a) throws Exception {"
                    + " Thread.sleep(60_000); }\n"));
    write(
        "threads",
        "Square.java",
        run(
            "    for (int i = 0; i < 100000; i++) { Thread t = new Thread(() -> { try {"
                + " Thread.sleep(60000); } catch (InterruptedException e) { } }); t.setDaemon(true);"
                + " t.start(); }"));
    write(
        cpuSubs,
        "spin",
        "Square.java",
        program(
            "",
            "  private long n;\n  public Square() { while (n >= 0) { n++; } }\n"
                + "  public void run(ArRobot robot) {}"));
    write(
        "allocate",
        "Square.java",
        run(
            "    List<long[]> hoard = new ArrayList<>();\n"
                + "    while (true) { hoard.add(new long[1 << 20]); }"));
    write("exit", "Square.java", run("    System.exit(0);"));
    write(
        "stray",
        "Square.java",
        run(
            "    new ProcessBuilder(\""
                + java
                + "\", \"-cp\", \"/sandbox/classes\", \"Sleeper\").start();\n"
                + "    robot.getClock().sleepMillis(500);"));
    write(
        "stray",
        "Sleeper.java",
        "public class Sleeper { public static void main(String[] a) throws Exception {"
            + " Thread.sleep(90_000); } }");
    // many small files, each far below the file-size limit
    write(
        "hoarder",
        "Square.java",
        run(
            "    for (int i = 0; i < 20000; i++) { Files.writeString(Path.of(\"/sandbox/tmp/f\" +"
                + " i), \"x\"); }\n    System.out.println(\"wrote them all\");"));
    // a link to a classmate's file is not copied: the submission is empty
    Files.createDirectories(subs.resolve("linker"));
    Files.createSymbolicLink(
        subs.resolve("linker/Square.java"), subs.resolve("alice/Square.java").toAbsolutePath());
    // many files each below the file-size limit, more than the scratch folder may hold together
    write(
        "diskfill",
        "Square.java",
        run(
            "    byte[] mb = new byte[1 << 20];\n"
                + "    for (int i = 0; i < 8; i++) { try (var o = Files.newOutputStream(Path.of("
                + "\"/sandbox/tmp/big\" + i))) { for (int k = 0; k < 15; k++) { o.write(mb); } } }\n"
                + "    System.out.println(\"wrote 120 MB\");"));
    // a short source that keeps the compiler busy for minutes (nested least upper bounds)
    StringBuilder bomb =
        new StringBuilder(
            "import java.util.*;\npublic class Square {\n  void g(boolean b) {\n    var x = ");
    String a = "1";
    for (int i = 0; i < 7; i++) {
      a = "(b ? new ArrayList<>(List.of(" + a + ")) : new LinkedList<>(Set.of(" + a + ")))";
    }
    write(cpuSubs, "inference", "Square.java", bomb.append(a).append(";\n  }\n}\n").toString());
    // too much to hand in: a 50 MB source, and 10,000 sources
    Files.createDirectories(subs.resolve("hugefile"));
    try (RandomAccessFile f =
        new RandomAccessFile(subs.resolve("hugefile/Square.java").toFile(), "rw")) {
      f.setLength(50L << 20);
    }
    for (int i = 0; i < 10_000; i++) {
      Path d = subs.resolve("manyfiles").resolve("p" + i / 1000);
      Files.createDirectories(d);
      Files.writeString(d.resolve("C" + i + ".java"), "class C" + i + " {}");
    }
    // a folder with nothing to grade, a linked student folder, a stray file beside the students
    Files.createDirectories(subs.resolve("empty"));
    Files.writeString(subs.resolve("empty/README.txt"), "my solution is in my head");
    Files.createDirectories(tmp.resolve("elsewhere/linked"));
    Files.writeString(tmp.resolve("elsewhere/linked/Square.java"), solution);
    Files.createSymbolicLink(subs.resolve("linked"), tmp.resolve("elsewhere/linked"));
    Files.writeString(subs.resolve("Square.java"), solution);
    // two names one report folder could confuse: the honest one keeps their own result
    write("a_b", "Square.java", solution);
    write(
        "a b",
        "Square.java",
        run(
            "    List<long[]> hoard = new ArrayList<>();\n"
                + "    while (true) { hoard.add(new long[1 << 20]); }"));
    before = snapshot(subs);
    before.putAll(snapshot(cpuSubs));
    before.putAll(snapshot(canary));

    StringWriter o = new StringWriter();
    StringWriter e = new StringWriter();
    int exit = grade(subs, out, 10, o, e);
    // 6 s: long enough for the endless constructor to be compiled and started on a loaded machine
    // (stopped while still compiling, it would be a compile limit, not a time-out)
    int cpuExit = grade(cpuSubs, cpuOut, 6, o, e);
    stdout = o.toString();
    stderr = e.toString();
    assertEquals(0, exit, stderr);
    assertEquals(0, cpuExit, stderr);
  }

  private static int grade(Path from, Path to, int seconds, StringWriter o, StringWriter e)
      throws IOException {
    int exit =
        ClassGrading.grade(
            GradeRequest.of("square", from, to)
                .withJobs(2)
                .withTimeout(Duration.ofSeconds(seconds))
                .withScratchRoot(scratch),
            new PrintWriter(o),
            new PrintWriter(e));
    List<String> names =
        SubmissionFolders.scan(from).submissions().stream()
            .map(SubmissionFolders.Submission::student)
            .toList();
    Map<String, String> folders = SubmissionFolders.reportFolders(names);
    for (String name : names) {
      byStudent.put(
          name, ResultFiles.read(to.resolve("students").resolve(folders.get(name)), name));
    }
    return exit;
  }

  @AfterAll
  static void closeServer() throws IOException {
    if (server != null) {
      server.close();
    }
  }

  private static Map<String, String> snapshot(Path root) throws IOException {
    Map<String, String> m = new TreeMap<>();
    try (Stream<Path> s = Files.walk(root)) {
      for (Path p : s.filter(Files::isRegularFile).toList()) {
        m.put(p.toString(), sha(Files.readAllBytes(p)));
      }
    }
    return m;
  }

  private static String sha(byte[] b) {
    try {
      return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(b));
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException(e);
    }
  }

  private static Grader.Result result(String student) {
    Grader.Result r = byStudent.get(student);
    assertTrue(r != null, "no result for " + student + "\n" + stdout);
    return r;
  }

  private static String output(String student) throws IOException {
    return Files.readString(out.resolve("students").resolve(student).resolve("output.txt"));
  }

  @Test
  void honestStudentsKeepExactlyTheGradeTheyGetInOneJvm(@TempDir Path work) throws IOException {
    Grade solution =
        Grading.compileAndGrade(
            new SquareAssignment(), Path.of("assignments/square/solution"), work.resolve("s"));
    Grade starter =
        Grading.compileAndGrade(
            new SquareAssignment(), Path.of("assignments/square/starter"), work.resolve("t"));
    assertEquals(10, solution.score(), solution.describe());
    for (String s : List.of("alice", "zoe")) {
      assertEquals(Status.GRADED, result(s).status(), stdout);
      assertEquals(solution.checks(), result(s).grade().checks(), stdout);
    }
    assertEquals(Status.GRADED, result("bob").status(), stdout);
    assertEquals(starter.checks(), result("bob").grade().checks(), stdout);
  }

  @Test
  void everyAttackGetsZeroAndItsOwnStatus() {
    Map<String, Status> expected =
        Map.ofEntries(
            Map.entry("forge", Status.GRADED),
            Map.entry("tamper", Status.GRADED),
            Map.entry("reader", Status.GRADED),
            Map.entry("outside", Status.GRADED),
            Map.entry("network", Status.GRADED),
            Map.entry("fork", Status.TOO_MANY_THREADS),
            Map.entry("threads", Status.TOO_MANY_THREADS),
            Map.entry("spin", Status.TIMEOUT),
            Map.entry("allocate", Status.OUT_OF_MEMORY),
            Map.entry("exit", Status.EXIT),
            Map.entry("hoarder", Status.TOO_MANY_FILES),
            Map.entry("diskfill", Status.TOO_MANY_FILES),
            Map.entry("inference", Status.COMPILE_LIMIT),
            Map.entry("hugefile", Status.TOO_LARGE),
            Map.entry("manyfiles", Status.TOO_LARGE),
            Map.entry("empty", Status.NO_SUBMISSION),
            Map.entry("linked", Status.NO_SUBMISSION),
            Map.entry("a b", Status.OUT_OF_MEMORY),
            Map.entry("linker", Status.NO_SUBMISSION));
    for (var e : expected.entrySet()) {
      Grader.Result r = result(e.getKey());
      assertEquals(e.getValue(), r.status(), e.getKey() + ": " + r.grade().describe());
      assertEquals(0, r.grade().score(), e.getKey() + ": " + r.grade().describe());
    }
    assertEquals(0, result("stray").grade().score());
    assertTrue(
        result("exit").grade().describe().contains("System.exit"),
        result("exit").grade().describe());
  }

  @Test
  void theySeeNothingOfTheClassAndReachNothingOutside() throws IOException {
    assertTrue(output("reader").contains("found 0 []"), output("reader"));
    // the processes it can see are its own: no grader, no path of the class or the report
    assertTrue(output("reader").contains("cmdline "), output("reader"));
    // its file descriptors are pipes: none names the report's output file
    assertTrue(output("reader").contains("fd pipe:"), output("reader"));
    assertFalse(output("reader").contains(subs.toString()), output("reader"));
    assertFalse(output("reader").contains(out.toString()), output("reader"));
    assertTrue(output("tamper").contains("found 0 []"), output("tamper"));
    String outside = output("outside");
    assertFalse(outside.contains("wrote"), outside);
    assertTrue(outside.contains("refused " + canary.resolve("pwned")), outside);
    assertTrue(output("network").contains("no network"), output("network"));
    assertFalse(output("network").contains("connected"), output("network"));
    try {
      server.accept().close();
      throw new AssertionError("a submission connected to the test's server");
    } catch (SocketTimeoutException expected) {
      // nobody came
    }
  }

  @Test
  void nothingOutsideTheScratchFoldersChanged() throws IOException {
    Map<String, String> after = snapshot(subs);
    after.putAll(snapshot(cpuSubs));
    after.putAll(snapshot(canary));
    assertEquals(before, after);
    assertFalse(Files.exists(Path.of("/tmp/pwned")));
    assertFalse(Files.exists(Path.of("/pwned")));
    // the grade files are the grader's: the forger's did not replace them
    assertFalse(Files.readString(out.resolve("students/forge/grade.txt")).contains("forged"));
    try (Stream<Path> s = Files.list(scratch)) {
      assertEquals(List.of(), s.toList(), "scratch folders left");
    }
  }

  @Test
  void noProcessOfTheirsIsLeft() {
    // this grading's sandboxes are the processes whose command line names its scratch root; what
    // they started are their descendants
    List<String> left =
        ProcessHandle.allProcesses()
            .filter(
                p -> p.info().commandLine().map(c -> c.contains(scratch.toString())).orElse(false))
            .flatMap(p -> Stream.concat(Stream.of(p), p.descendants()))
            .map(p -> p.pid() + " " + p.info().commandLine().orElse(""))
            .toList();
    assertEquals(List.of(), left);
  }

  @Test
  void everyStudentWhoseSubmissionCannotRunIsToldWhy() {
    assertTrue(stderr.contains("skipped Square.java: a file beside the students' folders"), stderr);
    assertTrue(
        result("inference").grade().describe().contains("compiling your code was still not done"),
        result("inference").grade().describe());
    assertTrue(
        result("hugefile").grade().describe().contains("Square.java is 50.0 MB"),
        result("hugefile").grade().describe());
    assertTrue(
        result("manyfiles").grade().describe().contains("10000 .java files (at most 200)"),
        result("manyfiles").grade().describe());
    assertTrue(
        result("empty").grade().describe().contains("there is no .java file in your folder"),
        result("empty").grade().describe());
    assertTrue(
        result("linked").grade().describe().contains("your folder is a link"),
        result("linked").grade().describe());
    assertTrue(
        result("linker").grade().notes().toString().contains("Square.java"),
        result("linker").grade().describe());
  }

  @Test
  void lookAlikeNamesStayTwoStudents() throws IOException {
    assertEquals(Status.GRADED, result("a_b").status(), result("a_b").grade().describe());
    assertEquals(10, result("a_b").grade().score());
    assertTrue(Files.readString(out.resolve("students/a_b~2/status.txt")).contains("student a b"));
    // re-grading "a b" re-grades that student, into their own folder, and a_b keeps theirs
    StringWriter o = new StringWriter();
    StringWriter e = new StringWriter();
    Path again = tmp.resolve("report-again");
    copyTree(out, again);
    int exit =
        ClassGrading.grade(
            GradeRequest.of("square", subs, again)
                .onlyStudent("a b")
                .withTimeout(Duration.ofSeconds(20))
                .withScratchRoot(scratch),
            new PrintWriter(o),
            new PrintWriter(e));
    assertEquals(0, exit, e.toString());
    assertTrue(o.toString().contains("[1/1] a b "), o.toString());
    assertTrue(
        Files.readString(again.resolve("students/a_b~2/status.txt")).startsWith("OUT_OF_MEMORY"));
    assertTrue(Files.readString(again.resolve("students/a_b/status.txt")).startsWith("GRADED"));
    String csv = Files.readString(again.resolve("gradebook.csv"));
    assertTrue(csv.contains("\na b,0,10,OUT_OF_MEMORY,"), csv);
    assertTrue(csv.contains("\na_b,10,10,GRADED,"), csv);
  }

  private static void copyTree(Path from, Path to) throws IOException {
    try (Stream<Path> s = Files.walk(from)) {
      for (Path p : s.toList()) {
        Path q = to.resolve(from.relativize(p).toString());
        if (Files.isDirectory(p)) {
          Files.createDirectories(q);
        } else {
          Files.copy(p, q);
        }
      }
    }
  }

  @Test
  void theReportsCarryTheOutcomes() throws IOException {
    String csv = Files.readString(out.resolve("gradebook.csv"));
    assertTrue(csv.startsWith("student,score,max,status,program ends,corner 1 reached"), csv);
    assertTrue(csv.contains("\nalice,10,10,GRADED,1,2,2,2,1,1,1\n"), csv);
    String cpuCsv = Files.readString(cpuOut.resolve("gradebook.csv"));
    assertTrue(cpuCsv.contains("\nspin,0,10,TIMEOUT,"), cpuCsv);
    String feedback = Files.readString(out.resolve("students/allocate/feedback.txt"));
    assertTrue(
        feedback.contains("Status: OUT_OF_MEMORY — Your program ran out of memory"), feedback);
    assertTrue(
        Files.exists(cpuOut.resolve("students/spin/grade.txt")),
        "a timed-out student has a grade file");
    assertTrue(stdout.contains("[22/22]"), stdout);
    assertTrue(stdout.contains("[2/2]"), stdout);
  }
}
