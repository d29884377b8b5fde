package org.jaria.site;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.tools.cli.JariaCli;
import picocli.CommandLine;

/**
 * What the getting-started guide's recipe tests share: the lines of a guide's command blocks, and
 * the guide's HelloRobot line run as written against a simulator.
 */
final class GuideRecipes {

  private final Path root = Repo.root();

  /** A {@code jaria} command started in a thread of this JVM, and what it prints. */
  record Started(Thread thread, StringWriter out) {

    /** Interrupts it (what Ctrl-C does to {@code jaria sim}) and waits up to 10 s for it to end. */
    boolean stop() throws InterruptedException {
      thread.interrupt();
      thread.join(TimeUnit.SECONDS.toMillis(10));
      return !thread.isAlive();
    }
  }

  /** Runs the command line with {@code args} in a new thread named {@code name}. */
  static Started start(List<String> args, String name) {
    StringWriter out = new StringWriter();
    CommandLine cli = JariaCli.commandLine();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(out, true));
    Thread t = new Thread(() -> cli.execute(args.toArray(String[]::new)), name);
    t.start();
    return new Started(t, out);
  }

  /** How the guide's HelloRobot line ended: within 90 s or not, its exit code, what it printed. */
  record HelloRobotRun(boolean done, int exit, String out) {}

  /**
   * Runs the guide's {@code java -cp ... HelloRobot.java -rh localhost} line as written against the
   * simulator on {@code port}: the launcher's jars if {@code package} built them (else this JVM's
   * class path), the sample's source in this repository.
   */
  HelloRobotRun runHelloRobot(String javaLine, int port) throws IOException, InterruptedException {
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
  List<String> guideLines(String guide, String prefix) throws IOException {
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
  static void waitForPort(int port, StringWriter log) throws InterruptedException {
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
