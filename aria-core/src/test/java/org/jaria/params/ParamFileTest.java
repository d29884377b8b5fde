package org.jaria.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ParamFileTest {

  private static final String SAMPLE =
      """
      ConfigVersion 2.0
      ;SectionFlags for :\s
      ; a comment

      Section General settings
      ;SectionFlags for General settings:\s
      Class Pioneer            ; general type
      robotradius 250.00000    ; lower-case keyword
      CompassPort              ; no value
      # hash comment
      Section Sonar parameters
      SonarNum 2
      SonarUnit 0 69 136 90
      SonarUnit 1 114 119 50   ; second
      [Old Style]
      Keyword   several words of value ; and a comment
      """;

  private static ParamFile sample() throws Exception {
    return ParamFile.read(new StringReader(SAMPLE), "sample.p");
  }

  @Test
  void sectionsEntriesAndComments() throws Exception {
    ParamFile f = sample();
    assertEquals(
        List.of("", "General settings", "Sonar parameters", "Old Style"), f.sectionNames());
    assertEquals(Optional.of("2.0"), f.get("ConfigVersion"));
    assertEquals(Optional.of("Pioneer"), f.get("class"));
    assertEquals(Optional.of("250.00000"), f.get("RobotRadius"));
    assertEquals(Optional.of(""), f.get("CompassPort"));
    assertEquals(List.of("0 69 136 90", "1 114 119 50"), f.getAll("SONARUNIT"));
    assertEquals(Optional.of("several words of value"), f.get("keyword"));
    ParamFile.Entry e = f.getEntry("SonarUnit").orElseThrow();
    assertEquals("Sonar parameters", e.section());
    assertEquals(13, e.line());
    assertEquals("second", f.getAllEntries("SonarUnit").get(1).comment());
    assertEquals("general type", f.getEntry("Class").orElseThrow().comment());
    assertEquals(Optional.empty(), f.get("NoSuchKeyword"));
    assertEquals(8, f.entries().size());
  }

  @Test
  void writeReproducesTheInput() throws Exception {
    StringWriter w = new StringWriter();
    sample().write(w);
    assertEquals(SAMPLE, w.toString());
  }

  @Test
  void crlfAndMissingFinalNewlineRoundTrip() throws Exception {
    String text = "ConfigVersion 2.0\r\nSection A\r\nKey value ; c\r\nOther 1";
    ParamFile f = ParamFile.read(new StringReader(text), "crlf.p");
    assertEquals(Optional.of("value"), f.get("Key"));
    assertEquals(Optional.of("1"), f.get("Other"));
    StringWriter w = new StringWriter();
    f.write(w);
    assertEquals(text, w.toString());
  }

  @ParameterizedTest
  @ValueSource(strings = {"p3dx-sh", "p3at-sh", "p3dx", "p3at"})
  void realFilesParseAndRoundTripByteForByte(String subtype) throws Exception {
    Path p = ReferenceParams.path(subtype);
    ParamFile f = ParamFile.read(p);
    assertEquals(Optional.of(subtype), f.get("Subclass"));
    assertEquals(16, f.getAll("SonarUnit").size());
    assertTrue(f.sectionNames().contains("Laser 2 parameters"));
    StringWriter w = new StringWriter();
    f.write(w);
    assertEquals(Files.readString(p, StandardCharsets.ISO_8859_1), w.toString());
  }

  @Test
  void binaryFileIsRejectedWithFileAndLine(@TempDir Path dir) throws IOException {
    Path bin = dir.resolve("robot.p");
    Files.write(bin, new byte[] {'C', 'l', 'a', 's', 's', ' ', 'P', '\n', 0x00, 0x01, 'x', '\n'});
    ParamFormatException e = assertThrows(ParamFormatException.class, () -> ParamFile.read(bin));
    assertEquals(bin.toString(), e.getSourceName());
    assertEquals(2, e.getLine());
    assertTrue(e.getMessage().startsWith(bin + ":2: control character 0x00"), e.getMessage());
  }

  @Test
  void lineThatIsNotKeywordValueIsRejected() {
    ParamFormatException e =
        assertThrows(
            ParamFormatException.class,
            () -> ParamFile.parse("Section A\nRobotRadius 250\n position, mm>\n", "x.p"));
    assertEquals(3, e.getLine());
    assertTrue(e.getMessage().contains("is not a 'Keyword value' line"), e.getMessage());
    assertTrue(e.getMessage().startsWith("x.p:3: "), e.getMessage());
    ParamFormatException digit =
        assertThrows(ParamFormatException.class, () -> ParamFile.parse("3Keyword 1\n", "y.p"));
    assertEquals(1, digit.getLine());
  }

  @Test
  void badSectionHeadersAreRejected() {
    ParamFormatException noName =
        assertThrows(ParamFormatException.class, () -> ParamFile.parse("A 1\nSection\n", "s.p"));
    assertEquals(2, noName.getLine());
    assertTrue(noName.getMessage().contains("'Section' without a name"), noName.getMessage());
    ParamFormatException open =
        assertThrows(ParamFormatException.class, () -> ParamFile.parse("[Sonar\n", "s.p"));
    assertTrue(open.getMessage().contains("lacks the closing ']'"), open.getMessage());
    assertThrows(ParamFormatException.class, () -> ParamFile.parse("[ ]\n", "s.p"));
  }

  @Test
  void emptyInputIsAnEmptyFile() throws Exception {
    ParamFile f = ParamFile.parse("", "empty.p");
    assertTrue(f.entries().isEmpty());
    assertEquals(List.of(), f.sectionNames());
    StringWriter w = new StringWriter();
    f.write(w);
    assertEquals("", w.toString());
  }
}
