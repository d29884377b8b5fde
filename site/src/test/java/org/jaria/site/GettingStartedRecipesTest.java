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
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

/**
 * The getting-started guide's recipes run as a reader follows them, in English and Spanish: the
 * simulator started by the guide's own {@code ./jaria sim} line, and the guide's {@code java} line
 * running the HelloRobot sample against it over TCP. (A class of its own, apart from {@link
 * DocsCommandsTest}, so that the build's test JVMs run the two side by side.)
 */
@Tag("slow")
class GettingStartedRecipesTest {

  private final Path root = Repo.root();

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
      HelloRobotRun run = runHelloRobot(javaLines.get(0), port);
      assertTrue(run.done(), "HelloRobot finished:\n" + run.out());
      assertEquals(0, run.exit(), run.out());
      assertTrue(run.out().contains("Connected to"), run.out());
      assertTrue(run.out().contains("Done; the robot believes it is at"), run.out());
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
        HelloRobotRun run = runHelloRobot(javaLines.get(0), port);
        assertTrue(run.done() && run.exit() == 0, "HelloRobot finished:\n" + run.out());
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

  /** How the guide's HelloRobot line ended: within 90 s or not, its exit code, what it printed. */
  private record HelloRobotRun(boolean done, int exit, String out) {}

  /**
   * Runs the guide's {@code java -cp ... HelloRobot.java -rh localhost} line as written against the
   * simulator on {@code port}: the launcher's jars if {@code package} built them (else this JVM's
   * class path), the sample's source in this repository.
   */
  private HelloRobotRun runHelloRobot(String javaLine, int port)
      throws IOException, InterruptedException {
    List<String> words = new ArrayList<>(ShellWords.split(javaLine));
    String cp = words.get(2);
    boolean built = Files.isRegularFile(root.resolve("tools/target/jaria-tools.jar"));
    words.set(0, Path.of(System.getProperty("java.home"), "bin", "java").toString());
    words.set(2, built ? cp.replace("tools/", root + "/tools/") : testClassPath());
    int src = words.indexOf("HelloRobot.java");
    words.set(
        src, root.resolve("site/src/test/java/org/jaria/site/samples/HelloRobot.java").toString());
    words.add("-rrtp");
    words.add(String.valueOf(port));
    Process p = new ProcessBuilder(words).redirectErrorStream(true).start();
    boolean done = p.waitFor(90, TimeUnit.SECONDS);
    if (!done) {
      p.destroyForcibly();
    }
    String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    return new HelloRobotRun(done, done ? p.exitValue() : -1, out);
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
