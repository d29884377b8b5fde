package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Expected failures through the real command line: each said once, on one line naming the command,
 * with one hint in the user's own option names, and no stack trace or usage listing.
 */
class JariaCliErrorsTest {

  private record Run(int status, String out, String err) {
    String all() {
      return out + err;
    }
  }

  private static Run jaria(String... args) {
    CommandLine cli = JariaCli.commandLine();
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

  private static int count(String text, String part) {
    int n = 0;
    for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
      n++;
    }
    return n;
  }

  @Test
  void aMalformedMapIsOneLineNamingTheFileAndTheRow(@TempDir Path dir) throws IOException {
    Path bad = Files.writeString(dir.resolve("bad.map"), "2D-Map\nLINES\ngarbage here\n");
    Run r = jaria("sim", "--map", bad.toString(), "--seconds", "1");
    assertEquals(1, r.status(), r.all());
    assertNoTraceNorUsage(r);
    assertEquals(1, r.err().lines().count(), r.err());
    assertTrue(r.err().startsWith("jaria sim: " + bad + ":3:"), r.err());
  }

  @Test
  void aMissingMapIsTheMessageAndOneHintNotTheUsage() {
    Run r = jaria("sim", "--map", "nothere.map");
    assertEquals(2, r.status(), r.all());
    assertNoTraceNorUsage(r);
    assertEquals(
        List.of(
            "jaria sim: map file nothere.map does not exist",
            "Run 'jaria sim --help' for its options."),
        r.err().lines().toList());
  }

  @Test
  void aPortInUseSaysSoOnce() throws IOException {
    try (ServerSocket taken = new ServerSocket(0)) {
      Run r = jaria("sim", "--map", "hall", "--port", String.valueOf(taken.getLocalPort()));
      assertEquals(1, r.status(), r.all());
      assertNoTraceNorUsage(r);
      assertTrue(r.err().contains("is in use") && r.err().contains("--port"), r.err());
      assertEquals(1, r.err().lines().count(), r.err());
    }
  }

  @Test
  void nothingListeningIsSaidOnceWithTheUsersOwnOption() throws IOException {
    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    Run r = jaria("demo", "--remote", "127.0.0.1:" + port, "--seconds", "1");
    assertEquals(1, r.status(), r.all());
    assertNoTraceNorUsage(r);
    assertEquals(1, count(r.all(), "nothing accepts connections"), r.all());
    assertTrue(r.err().contains("--remote") && !r.all().contains("-rrtp"), r.all());
  }

  @Test
  void anUnknownOptionSuggestsTheRightOne() {
    Run r = jaria("demo", "--sekonds", "3");
    assertEquals(2, r.status(), r.all());
    assertNoTraceNorUsage(r);
    assertTrue(r.err().contains("--seconds"), r.err());
  }

  @Test
  void aMapTheMapperCannotFindIsSaidBeforeAnyWindow() {
    Run r = jaria("mapper", "nowhere-" + StandardCharsets.UTF_8.name());
    assertEquals(2, r.status(), r.all());
    assertTrue(r.err().startsWith("jaria mapper: there is no map file"), r.err());
    assertTrue(r.err().contains("bundled: office, hall, columbia"), r.err());
  }
}
