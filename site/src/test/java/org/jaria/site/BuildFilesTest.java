package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** The build files agree where the README's commands depend on them. */
class BuildFilesTest {

  private final Path root = Repo.root();

  /**
   * {@code ./mvnw spotless:apply} at the root (the README's formatting command) needs the plugin in
   * every module of the reactor, the BOM too, which has no parent and so names the version itself.
   */
  @Test
  void theBomDeclaresTheSpotlessPluginTheBuildUses() throws IOException {
    String rootPom = Files.readString(root.resolve("pom.xml"));
    Matcher v = Pattern.compile("<spotless.version>([^<]+)</spotless.version>").matcher(rootPom);
    assertTrue(v.find(), "the root pom pins spotless.version");
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
}
