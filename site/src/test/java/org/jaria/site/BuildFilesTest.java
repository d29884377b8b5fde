package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The build files agree where the README's commands depend on them. */
class BuildFilesTest {

  private final Path root = Repo.root();

  /**
   * {@code ./mvnw spotless:apply} at the root (the README's formatting command) needs the plugin in
   * every module of the reactor, the BOM too, which has no parent and so names the version itself.
   */
  @Test
  void theBomDeclaresTheSpotlessPluginTheBuildUses() throws IOException {
    String parentPom = Files.readString(root.resolve("parent/pom.xml"));
    Matcher v = Pattern.compile("<spotless.version>([^<]+)</spotless.version>").matcher(parentPom);
    assertTrue(v.find(), "the parent pom pins spotless.version");
    String bom = Files.readString(root.resolve("jaria-bom/pom.xml"));
    Matcher p =
        Pattern.compile(
                "<artifactId>spotless-maven-plugin</artifactId>\\s*<version>([^<]+)</version>")
            .matcher(bom);
    assertTrue(p.find(), "jaria-bom declares spotless-maven-plugin");
    assertEquals(v.group(1), p.group(1), "jaria-bom's spotless version");
  }

  /** The README's test command is the one .ci/run runs. */
  @Test
  void ciRunsTheReadmesTestCommand() throws IOException {
    String readme = Files.readString(root.resolve("README.md"));
    String ci = Files.readString(root.resolve(".ci/run"));
    assertTrue(readme.contains("\n    ./mvnw verify\n"), "README shows ./mvnw verify");
    assertTrue(ci.strip().endsWith("./mvnw -B verify"), "ci ends with the README's command");
  }

  /**
   * The Javadoc tool no longer runs in every build (its jars are made with {@code -Prelease}), so
   * its checks must run inside javac: the main sources' compile gets {@code jaria.javac.doclint},
   * and that option fails a public comment with a broken link or unclosed HTML, as the Javadoc tool
   * did.
   */
  @Test
  void theMainCompileChecksJavadocAsTheJavadocToolDid(@TempDir Path dir) throws IOException {
    String parentPom = Files.readString(root.resolve("parent/pom.xml"));
    Matcher option =
        Pattern.compile("<jaria.javac.doclint>([^<]+)</jaria.javac.doclint>").matcher(parentPom);
    assertTrue(option.find(), "the parent pom sets jaria.javac.doclint");
    assertTrue(
        Pattern.compile(
                "<id>default-compile</id>\\s*<configuration>\\s*"
                    + "<compilerArgs combine.children=\"append\">\\s*"
                    + "<arg>\\$\\{jaria.javac.doclint}</arg>")
            .matcher(parentPom)
            .find(),
        "the main compile (default-compile) passes jaria.javac.doclint to javac");

    Path broken = dir.resolve("Broken.java");
    Files.writeString(
        broken,
        """
        /** A class whose comment links {@link Nowhere} and leaves <b>bold open. */
        public class Broken {
          /** A private helper's comment is not the Javadoc tool's business: <tt&> */
          private void helper() {}
        }
        """);
    InProcessJavac.Result r =
        InProcessJavac.compile(List.of(option.group(1), "-d", dir.toString()), broken);
    boolean ok = r.ok();
    String log = r.log();
    assertTrue(!ok, "javac with " + option.group(1) + " must fail the broken comment:\n" + log);
    assertTrue(log.contains("reference not found"), log);
    assertTrue(log.contains("element not closed: b"), log);
    assertTrue(!log.contains("Broken.java:3"), "private members are not checked\n" + log);
  }

  /**
   * What {@code ./jaria} runs (cli/target/lib beside cli's jar, made by {@code package}, which
   * {@code ./mvnw verify} runs before these tests) holds the log output's backend, the command
   * line's commands and grading, and neither JavaFX nor OpenCV.
   */
  @Test
  void theLaunchersLibrariesHaveTheLogBackendAndGrading() throws IOException {
    Path lib = root.resolve("cli/target/lib");
    assumeTrue(Files.isDirectory(lib), "cli is not packaged (./mvnw verify packages it)");
    List<String> jars;
    try (var files = Files.list(lib)) {
      jars = files.map(p -> p.getFileName().toString()).sorted().toList();
    }
    for (String wanted : List.of("slf4j-simple-", "tools-", "classroom-", "picocli-")) {
      assertTrue(jars.stream().anyMatch(j -> j.startsWith(wanted)), wanted + " in " + jars);
    }
    for (String unwanted : List.of("javafx-", "opencv-")) {
      assertTrue(jars.stream().noneMatch(j -> j.startsWith(unwanted)), unwanted + " in " + jars);
    }
  }
}
