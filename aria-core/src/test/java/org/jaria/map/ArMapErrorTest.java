package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ArMapErrorTest {

  private static MapFormatException fail(String text) {
    return assertThrows(
        MapFormatException.class, () -> ArMap.read(new StringReader(text), "bad.map"));
  }

  @ParameterizedTest(name = "{0}")
  @CsvSource(
      delimiter = '|',
      quoteCharacter = '`',
      textBlock =
          """
          Cairn: Goal abc 5 0 "" ICON "g"                | 2 | Cairn x 'abc' is not a number
          Cairn: Goal 1 2 0 "" ICON                      | 2 | needs 7 words
          Cairn: ForbiddenLine 1 2 0 "" ICON "" 1 2 3    | 2 | found 10
          Cairn: Goal 1 2 0 "" ICON "no end              | 2 | double quote is not closed
          Cairn: ForbiddenArea 0 0 0 "" ICON "" 1 2 x 4  | 2 | Cairn x2 'x' is not a number
          Cairn: Goal 1 2 NaN "" ICON "g"                | 2 | Cairn heading 'NaN' is not a number
          MapInfo:                                       | 2 | MapInfo without a type class
          Resolution: fine                               | 2 | Resolution 'fine' is not a number
          MinPos: 1                                      | 2 | MinPos needs 2 number(s), found 1
          NumPoints: -5                                  | 2 | NumPoints must be a whole number
          PointsAreSorted: maybe                         | 2 | PointsAreSorted must be true or false
          """)
  void badHeaderLines(String line, int lineNo, String message) {
    MapFormatException e = fail("2D-Map\n" + line + "\nDATA\n");
    assertEquals("bad.map", e.getSourceName());
    assertEquals(lineNo, e.getLine());
    assertTrue(e.getMessage().startsWith("bad.map:" + lineNo + ": "), e.getMessage());
    assertTrue(e.getMessage().contains(message), e.getMessage());
  }

  @Test
  void linesRowWithThreeNumbers() {
    MapFormatException e = fail("2D-Map\nLINES\n0 0 1 1\n0 0 1\nDATA\n");
    assertEquals(4, e.getLine());
    assertTrue(e.getMessage().contains("LINES row '0 0 1' has 3 number(s)"), e.getMessage());
    assertTrue(e.getMessage().contains("'x1 y1 x2 y2'"), e.getMessage());
  }

  @Test
  void dataRowWithText() {
    MapFormatException e = fail("2D-Map\nDATA\n1 2\n3 four\n");
    assertEquals(4, e.getLine());
    assertTrue(
        e.getMessage().contains("DATA row '3 four' holds 'four' where a number belongs"),
        e.getMessage());
    MapFormatException extra = fail("2D-Map\nDATA\n1 2 3\n");
    assertTrue(extra.getMessage().contains("has more than 2 numbers"), extra.getMessage());
    MapFormatException header = fail("2D-Map\nDATA\nCairn: Goal 1 2 0 \"\" ICON \"late\"\n");
    assertEquals(3, header.getLine());
  }

  @Test
  void notAMap() {
    MapFormatException e = fail("Hello world\nDATA\n");
    assertEquals(1, e.getLine());
    assertTrue(e.getMessage().contains("not an ArMap file"), e.getMessage());
    assertEquals(1, fail("").getLine());
  }

  @Test
  void duplicateSections() {
    MapFormatException e = fail("2D-Map\nDATA\n1 2\nLINES\n0 0 1 1\nDATA\n3 4\n");
    assertEquals(6, e.getLine());
    assertTrue(e.getMessage().contains("a second DATA section"), e.getMessage());
  }

  @Test
  void binaryFile(@TempDir Path dir) throws Exception {
    Path p =
        Files.write(
            dir.resolve("x.map"),
            new byte[] {'2', 'D', '-', 'M', 'a', 'p', '\n', 1, 2, 3, 0, '\n'});
    MapFormatException e = assertThrows(MapFormatException.class, () -> ArMap.readFile(p));
    assertEquals(p.toString(), e.getSourceName());
    assertEquals(2, e.getLine());
    assertTrue(e.getMessage().contains("control character 0x01"), e.getMessage());
  }

  @Test
  void hugeDataValueIsRejected() {
    MapFormatException e = fail("2D-Map\nDATA\n99999999999 1\n");
    assertTrue(e.getMessage().contains("out of range"), e.getMessage());
  }

  @Test
  void bundledMapNamesAreChecked() {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> ArMap.loadBundled("../secret"));
    assertTrue(e.getMessage().contains("[office, hall, columbia]"), e.getMessage());
  }
}
