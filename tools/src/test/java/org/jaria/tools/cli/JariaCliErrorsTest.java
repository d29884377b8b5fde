package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
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
    assertEquals(1, r.status(), r.all());
    assertNoTraceNorUsage(r);
    assertEquals(
        List.of(
            "jaria sim: there is no map file "
                + Path.of("nothere.map").toAbsolutePath()
                + " and no bundled map named 'nothere': give a .map file's path or a bundled"
                + " map's name (bundled: office, hall, columbia)"),
        r.err().lines().toList());
  }

  /** Every command that takes a map says the same when the name leads nowhere. */
  @ParameterizedTest
  @ValueSource(
      strings = {
        "map info MAP",
        "sim --map MAP --seconds 1",
        "demo --map MAP --seconds 1",
        "demo goto --map MAP",
        "demo gyro --map MAP --seconds 1",
        "demo chase --map MAP --seconds 1",
        "demo navigate --map MAP",
        "demo guiserver --map MAP --port 0 --seconds 1"
        // mapper MAP: system-tests' AppsCommandLineTest (the map editor is an app)
      })
  void everyCommandThatTakesAMapSaysWhatIsWrongAndListsTheBundledOnes(
      String command, @TempDir Path dir) throws IOException {
    Path folder = Files.createDirectory(dir.resolve("maps"));
    for (String map : List.of(dir.resolve("nowhere").toString(), folder.toString())) {
      Run r = jaria(command.replace("MAP", map).split(" "));
      assertTrue(r.status() != 0, command + ": " + r.all());
      assertNoTraceNorUsage(r);
      assertEquals(1, r.err().lines().count(), command + ": " + r.err());
      String why = map.equals(folder.toString()) ? "is a folder, not a file" : "there is no map";
      assertTrue(r.err().contains(why), command + ": " + r.err());
      assertTrue(r.err().contains("bundled: office, hall, columbia"), command + ": " + r.err());
    }
  }

  @Test
  void aMissingFileForPacketsSaysSoAndWhatToCheck() {
    Run r = jaria("packets", "--file", "/nonexistent.bin");
    assertEquals(1, r.status(), r.all());
    assertEquals(
        "jaria packets: there is no file /nonexistent.bin: check the name, and the folder you run"
            + " from (relative names start there)",
        r.err().strip());
  }

  @Test
  void aBinaryFileGivenAsAMapIsQuotedAsPrintableText(@TempDir Path dir) throws IOException {
    byte[] garbage = new byte[400];
    new java.util.SplittableRandom(7).nextBytes(garbage);
    garbage[3] = 0x1b; // ESC: a terminal obeys what follows
    garbage[4] = '[';
    garbage[5] = '2';
    garbage[6] = 'J';
    garbage[7] = (byte) 0x9b; // CSI, the one-byte form
    Path bad = Files.write(dir.resolve("garbage.map"), garbage);
    for (String[] command :
        List.of(
            new String[] {"map", "info", bad.toString()},
            new String[] {"sim", "--map", bad.toString(), "--seconds", "1"})) {
      Run r = jaria(command);
      assertEquals(1, r.status(), r.all());
      assertTrue(r.err().contains("not an ArMap file"), r.err());
      assertTrue(r.err().contains("\\x1B[2J"), "ESC written as an escape: " + r.err());
      String text = r.all().replace("\n", "");
      for (int i = 0; i < text.length(); i++) {
        char c = text.charAt(i);
        assertFalse(
            Character.isISOControl(c) || c == '\uFFFD', "raw character " + (int) c + ": " + text);
      }
      assertTrue(r.err().length() < 400, "an excerpt, not the file: " + r.err());
    }
  }

  @Test
  void aPortInUseSaysSoOnce() throws IOException {
    try (ServerSocket taken = new ServerSocket(0)) {
      Run r = jaria("sim", "--map", "hall", "--port", String.valueOf(taken.getLocalPort()));
      assertEquals(1, r.status(), r.all());
      assertNoTraceNorUsage(r);
      assertTrue(r.err().contains("is in use") && r.err().contains("--port"), r.err());
      assertEquals(1, r.err().lines().count(), r.err());
      assertEquals("", r.out(), "nothing started, so no summary before the error");
    }
  }

  @Test
  void nothingListeningIsSaidOnceWithTheUsersOwnOption() throws IOException {
    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    // What the library logs (slf4j-simple) and the program prints go to System.err: catch it too.
    PrintStream realErr = System.err;
    ByteArrayOutputStream logged = new ByteArrayOutputStream();
    System.setErr(new PrintStream(logged, true, StandardCharsets.UTF_8));
    Run r;
    try {
      r = jaria("demo", "--remote", "127.0.0.1:" + port, "--seconds", "1");
    } finally {
      System.setErr(realErr);
    }
    String all = r.all() + logged.toString(StandardCharsets.UTF_8);
    assertEquals(1, r.status(), all);
    assertNoTraceNorUsage(r);
    assertEquals(1, count(all, "nothing accepts connections"), all);
    assertEquals(1, count(all, "jaria sim"), "one hint: " + all);
    assertEquals(1, count(r.err(), "jaria demo: "), all);
    assertTrue(r.err().contains("--remote") && !all.contains("-rrtp") && !all.contains("-rp"), all);
    assertFalse(all.contains("Robot connection options"), all);
  }

  @Test
  void anUnknownOptionSuggestsTheRightOne() {
    Run r = jaria("demo", "--sekonds", "3");
    assertEquals(2, r.status(), r.all());
    assertNoTraceNorUsage(r);
    assertTrue(r.err().contains("--seconds"), r.err());
  }
}
