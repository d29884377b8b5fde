package org.jaria.tools;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * The {@code ./jaria} launcher script, run for real by bash in a copy of the repository's layout
 * where {@code mvnw} and {@code java} are tiny fakes: the fake build counts its calls and, like
 * Maven with nothing to do, leaves an existing jar alone; the fake Java says it is 17 and prints
 * its arguments. Every file's time is set explicitly, so nothing depends on the clock's grain.
 */
class LauncherTest {

  private static final String[] MODULES = {
    "aria-core",
    "simulator",
    "jaria-testing",
    "arnl-sonar",
    "mapping",
    "aria-net",
    "arnl-net",
    "acts-vision",
    "classroom",
    "web",
    "sim-vision",
    "desktop-spi",
    "sim-guiserver",
    "tools",
    "cli"
  };

  /** What the apps are built from besides the command line's modules. */
  private static final String[] APPS_MODULES = {"acts-camera", "apps"};

  @TempDir Path repo;
  private final Instant now = Instant.now();

  @BeforeEach
  void fakeRepository() throws IOException {
    Path script = Path.of("..", "jaria");
    assertTrue(Files.isRegularFile(script), "run from the module folder: " + script);
    Files.copy(script, repo.resolve("jaria"));
    executable(repo.resolve("jaria"));
    write(
        "mvnw",
        """
        #!/bin/sh
        module=cli
        previous=
        for a in "$@"; do
          if [ "$previous" = "-pl" ]; then module="$a"; fi
          previous="$a"
        done
        echo "build $module" >> "$(dirname "$0")/mvnw-calls"
        echo "[INFO] Scanning for projects..."
        echo "[INFO] Building JAria core (protocol, connections) 0.1.0-SNAPSHOT [2/8]"
        echo "[INFO] Building JAria tools (jaria command line) 0.1.0-SNAPSHOT [8/8]"
        for m in $(echo "$module" | tr , ' '); do
          mkdir -p "$m/target/lib"
          # Like Maven when nothing changed: an existing jar is not rewritten.
          jar="$m/target/jaria-$m.jar"
          [ -f "$jar" ] || echo jar > "$jar"
        done
        """);
    executable(repo.resolve("mvnw"));
    write(
        "jdk/bin/java",
        """
        #!/bin/sh
        if [ "$1" = "-version" ]; then echo 'openjdk version "17.0.9" 2023-10-17' >&2; exit 0; fi
        echo "java $*"
        """);
    executable(repo.resolve("jdk/bin/java"));
    write("pom.xml", "<project/>");
    write("parent/pom.xml", "<project/>");
    List<String> all = new ArrayList<>(Arrays.asList(MODULES));
    all.addAll(Arrays.asList(APPS_MODULES));
    all.addAll(List.of("examples", "site", "jaria-bom"));
    for (String m : all) {
      write(m + "/pom.xml", "<project/>");
      write(m + "/src/main/java/A.java", "class A {}");
      write(m + "/src/test/java/ATest.java", "class ATest {}");
    }
    try (var files = Files.walk(repo)) {
      for (Path f : files.filter(Files::isRegularFile).toList()) {
        age(f, Duration.ofHours(2));
      }
    }
  }

  @Test
  void whatVerifyWritesUnderTargetDoesNotRebuildAndANoOpBuildIsNotRepeated() throws Exception {
    Result first = jaria(Map.of(), "version");
    assertEquals(1, builds(), first.err);
    assertTrue(first.out.contains("java ") && first.out.contains(" version"), first.out);

    // What `./mvnw verify` and `./mvnw install` leave behind, newer than the jar.
    for (String f :
        List.of(
            "examples/target/its/pom.xml",
            "examples/target/its/consumer/pom.xml",
            "site/target/site/examples/consumer/pom.xml",
            "aria-core/target/classes/A.class",
            "tools/target/test-classes/ATest.class",
            "examples/src/main/java/B.java",
            "aria-core/src/test/java/BTest.java")) {
      write(f, "x");
      age(repo.resolve(f), Duration.ofHours(-1)); // newer than anything built
    }
    Result second = jaria(Map.of(), "version");
    Result third = jaria(Map.of(), "version");
    assertEquals(1, builds(), second.err + third.err);
    assertEquals("", second.err + third.err);
  }

  @Test
  void aChangedSourceIsBuiltOnceEvenWhenTheJarStaysTheSame() throws Exception {
    jaria(Map.of(), "version");
    Path jar = repo.resolve("cli/target/jaria-cli.jar");
    age(jar, Duration.ofMinutes(30)); // an older build
    age(repo.resolve("cli/target/jaria-build.stamp"), Duration.ofMinutes(30));
    Path source = repo.resolve("simulator/src/main/java/A.java");
    age(source, Duration.ofMinutes(10)); // edited since

    Result rebuilt = jaria(Map.of(), "version");
    assertEquals(2, builds(), rebuilt.err);
    assertTrue(rebuilt.err.contains("jaria: built in"), rebuilt.err);
    Result again = jaria(Map.of(), "version");
    assertEquals(2, builds(), "the unchanged jar is not rebuilt again:\n" + again.err);

    age(repo.resolve("pom.xml"), Duration.ofMinutes(-10)); // the root pom is built from too
    jaria(Map.of(), "version");
    assertEquals(3, builds());

    // and so are the build settings every module inherits
    age(repo.resolve("pom.xml"), Duration.ofHours(1)); // only the settings are newer now
    age(repo.resolve("parent/pom.xml"), Duration.ofMinutes(-15));
    jaria(Map.of(), "version");
    assertEquals(4, builds());
  }

  @Test
  void jariaNoBuildRunsWhatIsThereWithoutLooking() throws Exception {
    jaria(Map.of(), "version");
    age(repo.resolve("aria-core/src/main/java/A.java"), Duration.ofHours(-1));
    Result r = jaria(Map.of("JARIA_NO_BUILD", "1"), "version");
    assertEquals(1, builds(), r.err);
    assertTrue(r.out.contains("version"), r.out);
  }

  /**
   * The progress lines come without GNU {@code tail}: here a {@code tail} that, like macOS's,
   * refuses {@code --pid} comes first on the PATH.
   */
  @Test
  void progressLinesShowWithoutGnuTail() throws Exception {
    write(
        "bin/tail",
        """
        #!/bin/sh
        for a in "$@"; do
          case "$a" in --pid*) echo "tail: illegal option -- -" >&2; exit 1 ;; esac
        done
        exec /usr/bin/tail "$@"
        """);
    executable(repo.resolve("bin/tail"));
    String path = repo.resolve("bin") + ":" + System.getenv("PATH");
    Result r = jaria(Map.of("PATH", path), "version");
    assertEquals(1, builds(), r.err);
    assertTrue(r.err.contains("[2/8] JAria core (protocol, connections)"), r.err);
    assertTrue(r.err.contains("[8/8] JAria tools (jaria command line)"), r.err);
    assertTrue(r.err.contains("jaria: built in"), r.err);
  }

  /** What the launcher says the first build takes is what the README says. */
  @Test
  void theLauncherAndTheReadmeGiveTheSameFirstBuildTime() throws IOException {
    String script = Files.readString(Path.of("..", "jaria"), StandardCharsets.UTF_8);
    Matcher m = Pattern.compile("(?m)^build_time=\"([^\"]*)\"").matcher(script);
    assertTrue(m.find(), "the launcher names the time");
    String readme = Files.readString(Path.of("..", "README.md"), StandardCharsets.UTF_8);
    String said = readme.replaceAll("\\s+", " ");
    assertTrue(
        said.contains(
            "The first run builds the command line first, printing a line per module: "
                + m.group(1)),
        "the README says " + m.group(1));
  }

  /**
   * The script's module lists are exactly what {@code ./mvnw -pl cli -am} and {@code -pl cli,apps
   * -am} build.
   */
  @Test
  void theModulesWatchedAreWhatToolsAndTheAppsAreBuiltFrom() throws Exception {
    String script = Files.readString(Path.of("..", "jaria"), StandardCharsets.UTF_8);
    Matcher m = Pattern.compile("(?m)^modules=\"([^\"]*)\"").matcher(script);
    assertTrue(m.find(), "the launcher names its modules");
    TreeSet<String> watched = new TreeSet<>(Arrays.asList(m.group(1).split(" ")));
    assertEquals(new TreeSet<>(Arrays.asList(MODULES)), watched);
    assertEquals(reactorOf(Path.of(".."), "cli"), watched);
    Matcher a = Pattern.compile("(?m)^apps_modules=\"\\$modules ([^\"]*)\"").matcher(script);
    assertTrue(a.find(), "the launcher names the apps' modules");
    TreeSet<String> apps = new TreeSet<>(watched);
    apps.addAll(Arrays.asList(a.group(1).split(" ")));
    TreeSet<String> built = new TreeSet<>(reactorOf(Path.of(".."), "cli"));
    built.addAll(reactorOf(Path.of(".."), "apps"));
    assertEquals(built, apps);
    assertTrue(
        script.contains("build cli,apps "), "an app's command builds -pl cli,apps:\n" + script);
  }

  /**
   * The apps build beside the command line, not after it: apps depends on tools in no scope, so
   * Maven starts it without waiting for tools' tests (what it shares with tools is in modules below
   * both).
   */
  @Test
  void theAppsDoNotDependOnTheCommandLine() throws Exception {
    assertFalse(reactorOf(Path.of(".."), "apps").contains("tools"));
    assertFalse(reactorOf(Path.of(".."), "apps").contains("cli"));
  }

  /**
   * tools builds beside the classroom module, whose tests take longest: only cli, which adds
   * grading to tools' commands, needs both.
   */
  @Test
  void theCommandsBuildBesideTheClassroom() throws Exception {
    assertFalse(reactorOf(Path.of(".."), "tools").contains("classroom"));
    assertTrue(reactorOf(Path.of(".."), "cli").containsAll(List.of("tools", "classroom")));
  }

  /**
   * A desktop app is built the first time it is asked for, once, and runs with the apps' class path
   * beside the command line's; the command line's commands neither build nor use it.
   */
  @Test
  void theAppsAreBuiltOnFirstUseOnlyAndOnlyTheirCommandsUseThem() throws Exception {
    Result cli = jaria(Map.of(), "demo");
    assertEquals(List.of("build cli"), calls(), cli.err);
    assertTrue(cli.out.contains("cli/target/jaria-cli.jar"), cli.out);
    assertFalse(cli.out.contains("apps/target"), cli.out);

    Result app = jaria(Map.of(), "mapper", "office.map");
    assertEquals(List.of("build cli", "build cli,apps"), calls(), app.err);
    assertTrue(app.err.contains("building the desktop apps and cameras"), app.err);
    assertTrue(app.out.contains("apps/target/jaria-apps.jar"), app.out);
    assertTrue(app.out.contains("cli/target/jaria-cli.jar"), app.out);
    assertTrue(app.out.endsWith("org.jaria.tools.cli.JariaCli mapper office.map\n"), app.out);

    jaria(Map.of(), "screenshot", "mapper", "-o", "x.png");
    jaria(Map.of(), "version");
    assertEquals(List.of("build cli", "build cli,apps"), calls(), "nothing changed since");

    age(repo.resolve("apps/src/main/java/A.java"), Duration.ofMinutes(-10));
    jaria(Map.of(), "version");
    assertEquals(2, builds(), "an edited app does not rebuild the command line");
    jaria(Map.of(), "monitor");
    assertEquals(List.of("build cli", "build cli,apps", "build cli,apps"), calls());
  }

  /** Which commands run with the apps: apps, windows, live cameras and their benchmarks. */
  @Test
  void theCommandsThatNeedJavaFxOrOpenCvRunWithTheApps() throws Exception {
    Map<String, String> noBuild = Map.of("JARIA_NO_BUILD", "1");
    List<List<String>> withApps =
        List.of(
            List.of("mapper"),
            List.of("eztrain", "-f", "desk-scene"),
            List.of("monitor", "--help"),
            List.of("simview"),
            List.of("screenshot", "simview", "-o", "sim.png"),
            List.of("help", "mapper"),
            List.of("bench", "vision", "--quick"),
            List.of("bench", "mapper"),
            List.of("sim", "--map", "hall", "--gui"),
            List.of("demo", "--gui"),
            List.of("demo", "wander", "--gui"),
            List.of("demo", "guiserver", "--remote", "robot", "--camera", "0"),
            List.of("acts"),
            List.of("acts", "-d", "0", "-p", "0"),
            List.of("acts", "-P"));
    for (List<String> args : withApps) {
      Result r = jaria(noBuild, args.toArray(new String[0]));
      assertTrue(r.out.contains("apps/target/jaria-apps.jar"), args + ": " + r.out);
    }
    List<List<String>> commandLineOnly =
        List.of(
            List.of(),
            List.of("--help"),
            List.of("help"),
            List.of("help", "sim"),
            List.of("version"),
            List.of("demo"),
            List.of("demo", "guiserver"),
            List.of("sim", "--map", "hall"),
            List.of("bench", "sim"),
            List.of("acts", "-f", "desk-scene"),
            List.of("acts", "-fdesk-scene"),
            List.of("acts", "-h"),
            List.of("web"));
    for (List<String> args : commandLineOnly) {
      Result r = jaria(noBuild, args.toArray(new String[0]));
      assertTrue(r.out.contains("cli/target/jaria-cli.jar"), args + ": " + r.out);
      assertFalse(r.out.contains("apps/target"), args + ": " + r.out);
    }
    assertEquals(0, builds(), "JARIA_NO_BUILD builds nothing");
  }

  /** Module folders that {@code -pl MODULE -am} builds: it and its org.jaria dependencies. */
  private static Set<String> reactorOf(Path root, String start) throws Exception {
    Map<String, String> folderOf = new TreeMap<>();
    for (Element module : elements(pom(root.resolve("pom.xml")), "module")) {
      String folder = module.getTextContent().strip();
      Path p = root.resolve(folder).resolve("pom.xml");
      folderOf.put(child(pom(p).getDocumentElement(), "artifactId"), folder);
    }
    TreeSet<String> seen = new TreeSet<>();
    Deque<String> todo = new ArrayDeque<>(List.of(start));
    while (!todo.isEmpty()) {
      String folder = todo.pop();
      if (!seen.add(folder)) {
        continue;
      }
      for (Element dep : elements(pom(root.resolve(folder).resolve("pom.xml")), "dependency")) {
        if ("org.jaria".equals(child(dep, "groupId"))) {
          String target = folderOf.get(child(dep, "artifactId"));
          assertTrue(target != null, "a module of this build: " + child(dep, "artifactId"));
          todo.push(target);
        }
      }
    }
    return seen;
  }

  private static Document pom(Path p) throws Exception {
    return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(p.toFile());
  }

  private static List<Element> elements(Document d, String tag) {
    NodeList l = d.getElementsByTagName(tag);
    List<Element> out = new ArrayList<>();
    for (int i = 0; i < l.getLength(); i++) {
      out.add((Element) l.item(i));
    }
    return out;
  }

  private static String child(Element e, String tag) {
    for (Node n = e.getFirstChild(); n != null; n = n.getNextSibling()) {
      if (n instanceof Element c && c.getTagName().equals(tag)) {
        return c.getTextContent().strip();
      }
    }
    return "";
  }

  private record Result(String out, String err) {}

  private Result jaria(Map<String, String> env, String... args) throws Exception {
    List<String> cmd = new ArrayList<>(List.of("bash", repo.resolve("jaria").toString()));
    cmd.addAll(Arrays.asList(args));
    ProcessBuilder pb = new ProcessBuilder(cmd).directory(repo.toFile());
    pb.environment().remove("JARIA_NO_BUILD");
    pb.environment().put("JAVA_HOME", repo.resolve("jdk").toString());
    pb.environment().putAll(env);
    Path out = repo.resolve("out.txt");
    Path err = repo.resolve("err.txt");
    Process p = pb.redirectOutput(out.toFile()).redirectError(err.toFile()).start();
    assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher finished");
    String o = Files.readString(out, StandardCharsets.UTF_8);
    String e = Files.readString(err, StandardCharsets.UTF_8);
    assertEquals(0, p.exitValue(), o + e);
    return new Result(o, e);
  }

  private int builds() throws IOException {
    return calls().size();
  }

  /** The fake build's calls, one line each: "build cli" or "build cli,apps". */
  private List<String> calls() throws IOException {
    Path calls = repo.resolve("mvnw-calls");
    return Files.exists(calls) ? Files.readAllLines(calls) : List.of();
  }

  private void write(String file, String text) throws IOException {
    Path p = repo.resolve(file);
    Files.createDirectories(p.getParent());
    Files.writeString(p, text, StandardCharsets.UTF_8);
  }

  /** Sets a file's time to {@code ago} before the test started (negative: after). */
  private void age(Path p, Duration ago) throws IOException {
    Files.setLastModifiedTime(p, FileTime.from(now.minus(ago)));
  }

  private static void executable(Path p) throws IOException {
    Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("rwxr-xr-x"));
  }
}
