package org.jaria.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The command line's expected failures of the commands that need the apps module (the map editor, a
 * live camera), through the real {@code jaria} command line with the apps and the camera driver on
 * the class path: each said once, naming the command, with one hint and no stack trace or usage.
 */
class AppsCommandLineTest {

  private record Run(int status, String out, String err) {
    String all() {
      return out + err;
    }
  }

  private static Run jaria(String... args) {
    var cli = JariaCli.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(err, true));
    int status = cli.execute(args);
    return new Run(status, out.toString(), err.toString());
  }

  private static void assertNoTraceNorUsage(Run r) {
    assertFalse(r.all().contains("\tat ") || r.all().contains("Exception"), r.all());
    assertFalse(r.all().contains("Usage:"), r.all());
  }

  /** As every other command that takes a map (tools' JariaCliErrorsTest). */
  @Test
  void theMapperSaysWhatIsWrongWithAMapAndListsTheBundledOnes(@TempDir Path dir)
      throws IOException {
    Path folder = Files.createDirectory(dir.resolve("maps"));
    for (String map : List.of(dir.resolve("nowhere").toString(), folder.toString())) {
      Run r = jaria("mapper", map);
      assertTrue(r.status() != 0, r.all());
      assertNoTraceNorUsage(r);
      assertEquals(1, r.err().lines().count(), r.err());
      String why = map.equals(folder.toString()) ? "is a folder, not a file" : "there is no map";
      assertTrue(r.err().contains(why), r.err());
      assertTrue(r.err().contains("bundled: office, hall, columbia"), r.err());
    }
  }

  @Test
  void aMapTheMapperCannotFindIsSaidBeforeAnyWindow() {
    Run r = jaria("mapper", "nowhere-" + StandardCharsets.UTF_8.name());
    assertEquals(2, r.status(), r.all());
    assertTrue(r.err().startsWith("jaria mapper: there is no map file"), r.err());
    assertTrue(r.err().contains("bundled: office, hall, columbia"), r.err());
  }

  /** With the camera driver (acts-camera), ACTS lists the camera's parameters (-P). */
  @Test
  void actsListsCameraParameters() {
    Run r = jaria("acts", "-P");
    assertEquals(0, r.status(), r.all());
    assertTrue(r.out().contains("brightness"), r.out());
  }

  @Test
  void actsWithNoCameraGivesAClearMessage() {
    Run r = jaria("acts", "-d", "99", "-p", "0");
    assertEquals(1, r.status(), r.all());
    assertTrue(r.err().contains("no camera found at device index 99"), r.err());
  }
}
