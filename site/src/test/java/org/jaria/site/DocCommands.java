package org.jaria.site;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import org.jaria.tools.cli.JariaCli;
import picocli.CommandLine;

/**
 * The commands the documentation shows, and how the docs tests run them: in this JVM, through the
 * real command line, with long demos cut to a second and files written to a temporary folder.
 */
final class DocCommands {

  private final Path root = Repo.root();

  /** What failed (one entry per command) and how many commands ran. */
  record Result(List<String> failures, int ran) {}

  /** Subcommands quick and self-contained enough to run as written. */
  private static final Set<String> RUNNABLE =
      Set.of("version", "packets", "map", "demo", "grade", "help", "--help", "--version");

  List<String> lines(String prefix) throws IOException {
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

  /**
   * Runs the quick commands of {@code commands} whose subcommand {@code runs} accepts (each command
   * once), after checking that every command parses; files they write go to {@code tmp}.
   *
   * @return what failed, one entry per command, and how many ran
   */
  Result check(List<String> commands, Predicate<String> runs, Path tmp) {
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
      if (args.length == 0
          || !RUNNABLE.contains(args[0])
          || !runs.test(args[0])
          || !pathsExist(args)) {
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
    return new Result(failures, ran);
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
}
