package org.jaria.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A user's parameter file with a mistake: the robot runs on the bundled file for its subtype (never
 * on generic defaults without sonar), and the mistake is reported with file and line. Values that
 * cannot describe a robot are such mistakes.
 */
class BadUserParamsTest {

  private static String bundled(String subtype) throws IOException {
    try (InputStream in =
        ParamsLoader.class.getResourceAsStream(ArRobotParams.RESOURCE_DIR + subtype + ".p")) {
      return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1);
    }
  }

  /** The bundled file with the first line starting with {@code key} replaced. */
  private static String withLine(String text, String key, String line) {
    List<String> out = new ArrayList<>();
    boolean done = false;
    for (String l : text.split("\n", -1)) {
      if (!done && l.startsWith(key + " ")) {
        out.add(line);
        done = true;
      } else {
        out.add(l);
      }
    }
    assertTrue(done, key);
    return String.join("\n", out);
  }

  private static int lineOf(String text, String line) {
    return List.of(text.split("\n", -1)).indexOf(line) + 1;
  }

  @Test
  void oneBadLineMeansTheBundledFileNotGenericDefaultsWithoutSonar(@TempDir Path dir)
      throws Exception {
    String text = withLine(bundled("p3dx-sh"), "MaxVelocity", "MaxVelocity fast");
    Files.writeString(dir.resolve("p3dx-sh.p"), text, StandardCharsets.ISO_8859_1);
    ArRobotParams p = ArRobotParams.load("p3dx-sh", null, dir);
    assertEquals(16, p.getNumSonar(), "the bundled p3dx-sh sonar ring");
    assertTrue(p.getSources().get(p.getSources().size() - 1).startsWith("classpath:"));
    assertEquals(1, p.getProblems().size());
    String problem = p.getProblems().get(0);
    assertTrue(
        problem.contains("p3dx-sh.p:" + lineOf(text, "MaxVelocity fast")),
        "file and line: " + problem);
    assertTrue(problem.contains("MaxVelocity"), problem);
  }

  @Test
  void aGoodUserFileIsUsedAndSaysSo(@TempDir Path dir) throws Exception {
    String text = withLine(bundled("p3dx-sh"), "MaxVelocity", "MaxVelocity 1000");
    Files.writeString(dir.resolve("p3dx-sh.p"), text, StandardCharsets.ISO_8859_1);
    ArRobotParams p = ArRobotParams.load("p3dx-sh", null, dir);
    assertEquals(1000, p.getAbsoluteMaxVelocity());
    assertEquals(dir.resolve("p3dx-sh.p").toString(), p.getSources().get(1));
    assertEquals(List.of(), p.getProblems());
  }

  @Test
  void impossibleValuesAreErrorsWithKeyAndLine(@TempDir Path dir) throws Exception {
    String base = bundled("p3dx-sh");
    for (String[] c :
        new String[][] {
          {"DistConvFactor", "DistConvFactor 0"},
          {"Vel2Divisor", "Vel2Divisor 0"},
          {"AngleConvFactor", "AngleConvFactor -0.001"},
          {"RobotRadius", "RobotRadius -250"},
          {"RobotWidth", "RobotWidth -1"},
        }) {
      String text = withLine(base, c[0], c[1]);
      Path f = dir.resolve("p3dx-sh.p");
      Files.writeString(f, text, StandardCharsets.ISO_8859_1);
      ParamFormatException e =
          assertThrows(
              ParamFormatException.class, () -> ArRobotParams.loadStrict("p3dx-sh", null, dir));
      assertEquals(lineOf(text, c[1]), e.getLine(), e.getMessage());
      assertTrue(e.getMessage().contains(c[0]), e.getMessage());
      ArRobotParams lenient = ArRobotParams.load("p3dx-sh", null, dir);
      assertEquals(16, lenient.getNumSonar(), c[1]);
      assertEquals(1.0, lenient.getDistConvFactor(), c[1]);
      assertEquals(1, lenient.getProblems().size(), c[1]);
    }
  }

  @Test
  void sonarCountsThatDoNotMatchTheUnitsAreErrors() throws Exception {
    ParamFile extra =
        ParamFile.parse(
            "SonarNum 2\nSonarUnit 0 10 0 0\nSonarUnit 1 10 0 0\nSonarUnit 5 1 1 1\n", "x.p");
    ParamFormatException e =
        assertThrows(ParamFormatException.class, () -> ArRobotParams.defaults().overlay(extra));
    assertEquals(4, e.getLine(), e.getMessage());
    assertTrue(e.getMessage().contains("SonarUnit 5"), e.getMessage());
    ParamFile missing = ParamFile.parse("SonarNum 3\nSonarUnit 0 10 0 0\n", "y.p");
    ParamFormatException m =
        assertThrows(ParamFormatException.class, () -> ArRobotParams.defaults().overlay(missing));
    assertEquals(1, m.getLine(), m.getMessage());
    assertTrue(m.getMessage().contains("SonarNum"), m.getMessage());
  }

  /** Seeded damage to one line of a user's file: never generic defaults, never an exception. */
  @Test
  void fuzzedUserFilesAlwaysLeaveTheRobotWithItsSonar(@TempDir Path dir) throws Exception {
    String base = bundled("p3dx-sh");
    String[] lines = base.split("\n", -1);
    SplittableRandom rnd = new SplittableRandom(16);
    String[] junk = {"0", "-1", "x", "", "1e400", "NaN", "0.0", "-250", "99999999999", "true"};
    for (int i = 0; i < 300; i++) {
      String[] copy = lines.clone();
      int k = rnd.nextInt(copy.length);
      String[] words = copy[k].split("\\s+");
      if (words.length >= 2) {
        words[1] = junk[rnd.nextInt(junk.length)];
      }
      copy[k] = String.join(" ", words);
      Files.writeString(
          dir.resolve("p3dx-sh.p"), String.join("\n", copy), StandardCharsets.ISO_8859_1);
      ArRobotParams p = ArRobotParams.load("p3dx-sh", null, dir);
      assertFalse(p.getNumSonar() == 0 && p.getProblems().isEmpty(), "line: " + copy[k]);
      if (!p.getProblems().isEmpty()) {
        assertEquals(16, p.getNumSonar(), "bundled after: " + copy[k]);
        assertTrue(p.getProblems().get(0).contains("p3dx-sh.p:"), p.getProblems().get(0));
      }
      assertTrue(p.getDistConvFactor() > 0 && p.getVel2Divisor() > 0, copy[k]);
    }
  }
}
