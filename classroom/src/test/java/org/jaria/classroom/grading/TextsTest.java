package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jaria.classroom.square.SquareAssignment;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The checks' catalogue: both languages say the same things, and a Spanish grade is Spanish. */
class TextsTest {

  @Test
  void bothCataloguesHaveTheSameSentencesWithTheSameHoles() {
    Texts en = Texts.of("en");
    Texts es = Texts.of("es");
    assertEquals(en.keys(), es.keys());
    for (String k : en.keys()) {
      for (int i = 0; i < 8; i++) {
        String hole = "{" + i + "}";
        assertEquals(en.get(k).contains(hole), es.get(k).contains(hole), k + " " + hole);
      }
    }
    assertEquals("corner 2 reached", en.get("square.corner.name", 2));
    assertEquals("esquina 2 alcanzada", es.get("square.corner.name", 2));
  }

  @Test
  void aSpanishGradeHasNoEnglishCheckMessage(@TempDir Path work) throws IOException {
    SquareAssignment square = new SquareAssignment();
    Path empty = work.resolve("empty");
    Files.createDirectories(empty);
    Files.writeString(
        empty.resolve("Square.java"),
        """
        import org.jaria.classroom.RobotProgram;
        import org.jaria.robot.ArRobot;
        public class Square implements RobotProgram {
          public void run(ArRobot robot) {}
        }
        """,
        StandardCharsets.UTF_8);
    // its constructor is private: the student's side cannot make one and says so by key
    Path noConstructor = work.resolve("no-constructor");
    Files.createDirectories(noConstructor);
    Files.writeString(
        noConstructor.resolve("Square.java"),
        """
        import org.jaria.classroom.RobotProgram;
        import org.jaria.robot.ArRobot;
        public class Square implements RobotProgram {
          private Square() {}
          public void run(ArRobot robot) {}
        }
        """,
        StandardCharsets.UTF_8);
    List<String> english = englishPhrases();
    // the starter (a corner reached, one missed, the rest not reached) and a program that does
    // nothing (every check that passes earns nothing)
    for (Path dir : List.of(Path.of("assignments/square/starter"), empty, noConstructor)) {
      Path w = work.resolve("w-" + dir.getFileName() + dir.getNameCount());
      Grade en = Grading.compileAndGrade(square, dir, w.resolve("en"), Texts.of("en"));
      Grade es = Grading.compileAndGrade(square, dir, w.resolve("es"), Texts.of("es"));
      assertEquals(en.score(), es.score(), es.describe());
      assertEquals(en.checks().size(), es.checks().size(), es.describe());
      for (int i = 0; i < es.checks().size(); i++) {
        Check e = en.checks().get(i);
        Check s = es.checks().get(i);
        assertNotEquals(e.name(), s.name());
        assertNotEquals(e.message(), s.message());
        for (String phrase : english) {
          assertFalse(
              s.message().contains(phrase) || s.name().contains(phrase),
              "English '" + phrase + "' in " + s);
        }
      }
      if (dir.equals(noConstructor)) {
        assertEquals(
            "Square necesita un constructor público sin argumentos",
            es.checks().get(0).message(),
            es.describe());
      }
    }
  }

  /** Three or more plain words in a row. */
  private static final Pattern PHRASE = Pattern.compile("[a-zA-Z]+( +[a-zA-Z]+){2,}");

  /** The English catalogue's plain-word phrases of three words or more (no code, no holes). */
  private static List<String> englishPhrases() {
    Texts en = Texts.of("en");
    List<String> out = new ArrayList<>();
    for (String k : en.keys()) {
      // a hole breaks a phrase: what fills it may be anything
      Matcher m = PHRASE.matcher(en.get(k).replaceAll("\\{\\d\\}", "|"));
      while (m.find()) {
        out.add(m.group());
      }
    }
    return out;
  }
}
