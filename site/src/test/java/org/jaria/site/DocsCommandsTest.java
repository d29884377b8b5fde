package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

/**
 * Every command the documentation shows is checked: each {@code ./jaria ...} line parses with the
 * real command line, the quick ones run (in this JVM, with long demos cut to a second), every
 * {@code ./mvnw} line names modules and profiles that exist, and the getting-started {@code java}
 * line runs the sample against a simulator over TCP.
 */
@Tag("slow")
class DocsCommandsTest {

  private final Path root = Repo.root();

  /** Subcommands quick and self-contained enough to run as written. */
  private static final Set<String> RUNNABLE =
      Set.of("version", "packets", "map", "demo", "grade", "help", "--help", "--version");

  private List<String> lines(String prefix) throws IOException {
    Set<String> out = new LinkedHashSet<>();
    for (MarkdownBlocks.Block b : MarkdownBlocks.all(root)) {
      if (b.language().equals("java") || b.language().equals("cpp")) {
        continue;
      }
      for (String l : b.text().split("\n", -1)) {
        String s = l.strip();
        s = s.startsWith("$ ") ? s.substring(2) : s;
        if (s.startsWith(prefix)) {
          out.add(s);
        }
      }
    }
    return new ArrayList<>(out);
  }

  @Test
  void everyJariaCommandParsesAndTheQuickOnesRun(@TempDir Path tmp) throws IOException {
    List<String> commands = lines("./jaria");
    assertTrue(commands.size() >= 25, "only " + commands.size() + " ./jaria commands found");
    List<String> failures = new ArrayList<>();
    Set<List<String>> seen = new java.util.HashSet<>();
    int ran = 0;
    for (String line : commands) {
      List<String> words = ShellWords.split(line);
      if (!seen.add(words)) {
        continue; // the same command in another guide (or with another comment)
      }
      String[] args = words.subList(1, words.size()).toArray(String[]::new);
      try {
        JariaCli.commandLine().parseArgs(args);
      } catch (CommandLine.ParameterException e) {
        failures.add(line + "\n    does not parse: " + e.getMessage());
        continue;
      }
      if (args.length == 0 || !RUNNABLE.contains(args[0]) || !pathsExist(args)) {
        continue;
      }
      if (words.contains("--remote")) {
        continue; // needs a robot or simulator already running: RobotFactoryRecipeTest runs those
      }
      List<String> run = new ArrayList<>();
      for (String a : args) {
        run.add(Files.exists(root.resolve(a)) && a.contains("/") ? root.resolve(a).toString() : a);
      }
      if (args[0].equals("demo") && !run.contains("navigate")) {
        // The demos run in real time (30 s by default); a second shows they work.
        int at = run.indexOf("--seconds");
        if (at >= 0 && at + 1 < run.size()) {
          run.set(at + 1, "1");
        } else {
          run.add("--seconds");
          run.add("1");
        }
        if (run.contains("guiserver") && !run.contains("--port")) {
          run.add("--port"); // any free port: the test must not depend on 7272 being free
          run.add("0");
        }
      }
      if (args[0].equals("grade") && !run.contains("-o") && !run.contains("--out")) {
        run.add("--out");
        run.add(tmp.resolve("grade-" + ran).toString());
      }
      StringWriter out = new StringWriter();
      CommandLine cl = JariaCli.commandLine();
      cl.setOut(new PrintWriter(out));
      cl.setErr(new PrintWriter(out));
      long t0 = System.nanoTime();
      int exit = cl.execute(run.toArray(String[]::new));
      System.out.printf("%6d ms  %s%n", (System.nanoTime() - t0) / 1_000_000, line);
      ran++;
      if (exit != 0) {
        failures.add(line + "\n    exited " + exit + ": " + out);
      }
    }
    assertEquals(List.of(), failures);
    assertTrue(ran >= 10, "only " + ran + " commands ran");
  }

  /** Whether every argument that names a file or folder names one in the repository. */
  private boolean pathsExist(String[] args) {
    for (String a : args) {
      boolean pathLike =
          a.contains("/") || a.endsWith(".map") || a.endsWith(".java") || a.endsWith(".ppm");
      if (pathLike && !a.startsWith("-") && !Files.exists(root.resolve(a))) {
        return false;
      }
    }
    return true;
  }

  @Test
  void everyMavenCommandNamesRealModulesAndProfiles() throws IOException {
    List<String> commands = lines("./mvnw");
    assertTrue(commands.size() >= 3, commands.toString());
    // -pl names a module folder; -P a profile of the root pom or of a module's pom
    StringBuilder poms = new StringBuilder();
    try (java.util.stream.Stream<Path> s = Files.walk(root, 3)) {
      for (Path p : s.filter(f -> f.getFileName().toString().equals("pom.xml")).toList()) {
        if (!p.toString().contains("/target/")) {
          poms.append(Files.readString(p, StandardCharsets.UTF_8));
        }
      }
    }
    String pom = poms.toString();
    List<String> failures = new ArrayList<>();
    for (String line : commands) {
      List<String> w = ShellWords.split(line);
      for (int i = 1; i < w.size(); i++) {
        String a = w.get(i);
        String value = null;
        if ((a.equals("-pl") || a.equals("-P")) && i + 1 < w.size()) {
          value = w.get(++i);
        } else if (a.startsWith("-P") && a.length() > 2) {
          value = a.substring(2);
        }
        if (value == null) {
          continue;
        }
        for (String v : value.split(",", -1)) {
          boolean ok =
              a.startsWith("-P")
                  ? pom.contains("<id>" + v + "</id>")
                  : Files.isRegularFile(root.resolve(v).resolve("pom.xml"));
          if (!ok) {
            failures.add(line + ": no " + (a.startsWith("-P") ? "profile " : "module ") + v);
          }
        }
      }
    }
    assertEquals(List.of(), failures);
  }

  /**
   * The getting-started recipe as a reader follows it, in each guide (English and Spanish): step
   * 2's {@code ./jaria sim ...} line starts the simulator through the real command line (the same
   * map; only a free port and ten times real time added), and step 3's {@code java -cp
   * "tools/target/jaria-tools.jar:tools/target/lib/*" HelloRobot.java -rh localhost} runs the
   * sample as a single source file against it over TCP and must finish the square. Before {@code
   * package} has built the launcher's jars, this JVM's own class path stands in for them.
   */
  @ParameterizedTest
  @ValueSource(strings = {"docs/getting-started.md", "docs/es/primeros-pasos.md"})
  void theGettingStartedRecipeDrivesTheSquareAsWritten(String guide) throws Exception {
    List<String> simLines = guideLines(guide, "./jaria sim ");
    List<String> headless =
        simLines.stream().filter(l -> !l.contains("--gui") && !l.contains("--web")).toList();
    assertEquals(1, headless.size(), guide + " shows one headless simulator line: " + simLines);
    List<String> javaLines =
        guideLines(guide, "java -cp").stream().filter(l -> l.contains("-rh localhost")).toList();
    assertEquals(1, javaLines.size(), guide + " shows how to run HelloRobot.java: " + javaLines);

    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    List<String> sim = new ArrayList<>(ShellWords.split(headless.get(0)));
    sim.remove(0);
    sim.addAll(List.of("--port", String.valueOf(port), "--speedup", "10"));
    StringWriter simOut = new StringWriter();
    CommandLine simCli = JariaCli.commandLine();
    simCli.setOut(new PrintWriter(simOut, true));
    simCli.setErr(new PrintWriter(simOut, true));
    Thread simThread =
        new Thread(() -> simCli.execute(sim.toArray(String[]::new)), "guide-simulator");
    simThread.start();
    try {
      waitForPort(port, simOut);
      List<String> words = new ArrayList<>(ShellWords.split(javaLines.get(0)));
      String cp = words.get(2);
      boolean built = Files.isRegularFile(root.resolve("tools/target/jaria-tools.jar"));
      words.set(0, Path.of(System.getProperty("java.home"), "bin", "java").toString());
      words.set(2, built ? cp.replace("tools/", root + "/tools/") : testClassPath());
      int src = words.indexOf("HelloRobot.java");
      words.set(
          src,
          root.resolve("site/src/test/java/org/jaria/site/samples/HelloRobot.java").toString());
      words.add("-rrtp");
      words.add(String.valueOf(port));
      Process p = new ProcessBuilder(words).redirectErrorStream(true).start();
      boolean done = p.waitFor(90, TimeUnit.SECONDS);
      if (!done) {
        p.destroyForcibly();
      }
      String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
      assertTrue(done, "HelloRobot finished:\n" + out);
      assertEquals(0, p.exitValue(), out);
      assertTrue(out.contains("Connected to"), out);
      assertTrue(out.contains("Done; the robot believes it is at"), out);
    } finally {
      simThread.interrupt(); // what Ctrl-C does to `jaria sim`
      simThread.join(TimeUnit.SECONDS.toMillis(10));
    }
    assertTrue(!simThread.isAlive(), "the simulator stopped");
  }

  /**
   * The browser-only recipe as a reader follows it, in each guide: its {@code ./jaria sim ...
   * --web} line starts the simulator with the web view (a free port for the web view and the robot,
   * ten times real time), the printed address serves the page, a WebSocket client of that address
   * watches the robot's true pose as the page does, and step 3's HelloRobot line drives the square
   * that the watcher sees.
   */
  @ParameterizedTest
  @ValueSource(strings = {"docs/getting-started.md", "docs/es/primeros-pasos.md"})
  void theBrowserOnlyRecipeShowsTheSquareAsWritten(String guide) throws Exception {
    List<String> webLines =
        guideLines(guide, "./jaria sim ").stream().filter(l -> l.contains("--web")).toList();
    assertEquals(1, webLines.size(), guide + " shows one simulator line with --web");
    List<String> javaLines =
        guideLines(guide, "java -cp").stream().filter(l -> l.contains("-rh localhost")).toList();
    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    List<String> sim = new ArrayList<>(ShellWords.split(webLines.get(0)));
    sim.remove(0);
    sim.add(sim.indexOf("--web") + 1, "0"); // any free port: the test must not need 8088
    sim.addAll(List.of("--port", String.valueOf(port), "--speedup", "10"));
    StringWriter simOut = new StringWriter();
    CommandLine simCli = JariaCli.commandLine();
    simCli.setOut(new PrintWriter(simOut, true));
    simCli.setErr(new PrintWriter(simOut, true));
    Thread simThread = new Thread(() -> simCli.execute(sim.toArray(String[]::new)), "guide-web");
    simThread.start();
    try {
      waitForPort(port, simOut);
      long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
      while (!simOut.toString().contains("Web view: open")) {
        assertTrue(System.nanoTime() < deadline, "no web view address printed:\n" + simOut);
        // Watching another thread's printed output, which has no event to wait on.
        TimeUnit.MILLISECONDS.sleep(50);
      }
      java.util.regex.Matcher m =
          java.util.regex.Pattern.compile("Web view: open (http://\\S+) in a browser")
              .matcher(simOut.toString());
      assertTrue(m.find(), simOut.toString());
      java.net.URI page = java.net.URI.create(m.group(1));
      var http = java.net.http.HttpClient.newHttpClient();
      var body =
          http.send(
              java.net.http.HttpRequest.newBuilder(page).build(),
              java.net.http.HttpResponse.BodyHandlers.ofString());
      assertEquals(200, body.statusCode());
      assertTrue(body.body().contains("<canvas"), body.body());
      PoseWatcher watcher = PoseWatcher.open(page);
      try {
        List<String> words = new ArrayList<>(ShellWords.split(javaLines.get(0)));
        String cp = words.get(2);
        boolean built = Files.isRegularFile(root.resolve("tools/target/jaria-tools.jar"));
        words.set(0, Path.of(System.getProperty("java.home"), "bin", "java").toString());
        words.set(2, built ? cp.replace("tools/", root + "/tools/") : testClassPath());
        int src = words.indexOf("HelloRobot.java");
        words.set(
            src,
            root.resolve("site/src/test/java/org/jaria/site/samples/HelloRobot.java").toString());
        words.add("-rrtp");
        words.add(String.valueOf(port));
        Process p = new ProcessBuilder(words).redirectErrorStream(true).start();
        boolean done = p.waitFor(90, TimeUnit.SECONDS);
        if (!done) {
          p.destroyForcibly();
        }
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(done && p.exitValue() == 0, "HelloRobot finished:\n" + out);
        assertTrue(
            watcher.farthestMm() > 800,
            "the web view saw the robot drive its square: " + watcher.farthestMm() + " mm");
      } finally {
        watcher.close();
      }
    } finally {
      simThread.interrupt();
      simThread.join(TimeUnit.SECONDS.toMillis(10));
    }
    assertTrue(!simThread.isAlive(), "the simulator stopped");
  }

  /** The lines of one guide's command blocks that start with {@code prefix}. */
  private List<String> guideLines(String guide, String prefix) throws IOException {
    List<String> out = new ArrayList<>();
    for (MarkdownBlocks.Block b : MarkdownBlocks.all(root)) {
      if (!root.resolve(b.file()).normalize().equals(root.resolve(guide).normalize())
          || b.language().equals("java")) {
        continue;
      }
      for (String l : b.text().split("\n", -1)) {
        if (l.strip().startsWith(prefix)) {
          out.add(l.strip());
        }
      }
    }
    return out;
  }

  /** Waits (up to 30 s) until the simulator the guide started says it listens. */
  private static void waitForPort(int port, StringWriter log) throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
    while (!log.toString().contains("listening on TCP port " + port)) {
      if (System.nanoTime() > deadline) {
        throw new AssertionError("the simulator never listened on port " + port + ":\n" + log);
      }
      // Watching another thread's printed output, which has no event to wait on.
      TimeUnit.MILLISECONDS.sleep(50);
    }
  }

  private static String testClassPath() {
    return System.getProperty("java.class.path");
  }
}
