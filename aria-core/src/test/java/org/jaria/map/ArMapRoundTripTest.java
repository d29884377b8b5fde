package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ArMapRoundTripTest {

  @ParameterizedTest
  @ValueSource(strings = {"columbia.map", "triangle.map"})
  void realMapsRoundTripByteForByte(String name, @TempDir Path dir) throws Exception {
    Path in = ReferenceMaps.path(name);
    ArMap m = ArMap.readFile(in);
    Path out = dir.resolve(name);
    m.writeFile(out);
    assertArrayEquals(Files.readAllBytes(in), Files.readAllBytes(out));
    assertEquals(m, ArMap.readFile(out));
  }

  @ParameterizedTest
  @ValueSource(strings = {"office", "hall"})
  void bundledMapsRoundTrip(String name) throws Exception {
    ArMap m = ArMap.loadBundled(name);
    String text = ReferenceMaps.write(m);
    try (var in = ArMap.class.getResourceAsStream("/org/jaria/maps/" + name + ".map")) {
      assertEquals(new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8), text);
    }
    assertEquals(m, ReferenceMaps.parse(text));
  }

  @Test
  void crlfFileWithoutFinalNewlineRoundTrips() throws Exception {
    String text =
        "2D-Map\r\nMinPos: 0 0\r\nCairn: Goal 5 5 0 \"\" ICON \"g\"\r\nLINES\r\n0 0 1 1\r\nDATA\r\n3 4";
    ArMap m = ReferenceMaps.parse(text);
    assertEquals(text, ReferenceMaps.write(m));
    assertEquals(3, m.getPoints().x(0));
  }

  @Test
  void oddLayoutRowsAreKeptAsTheyWere() throws Exception {
    String text = "2D-Map\nLINES\n 0 0 1 1\n+2 2 3 3\n\n04 4 5 5\nDATA\n1  2\n-0 3\n1.0 2\n\n\n";
    ArMap m = ReferenceMaps.parse(text);
    assertEquals(3, m.getLines().size());
    assertEquals(3, m.getPoints().size());
    assertEquals(text, ReferenceMaps.write(m));
  }

  @Test
  void unknownLinesStayInPlace() throws Exception {
    String text =
        """
        2D-Map-Ex2
        Display: "Some display" 1 2
        Cairn: Goal 1 2 0.000000 "" ICON "a"
        CustomInfo: x y z
        _Cairn: Goal 3 4 0.000000 "" ICON "off"
        Cairn: Goal 5 6 0.000000 "" ICON "b"
        no colon here at all
        TaskInfo: "unterminated
        DATA
        """;
    ArMap m = ReferenceMaps.parse(text);
    m.replaceMapObject(m.findMapObject("b").orElseThrow(), ArMapObject.goal("b", 50, 60));
    String expected =
        text.replace(
            "Cairn: Goal 5 6 0.000000 \"\" ICON \"b\"",
            "Cairn: Goal 50 60 0.000000 \"\" ICON \"b\"");
    assertEquals(expected, ReferenceMaps.write(m));
  }

  @Test
  void latin1NamesSurviveAFileRoundTrip(@TempDir Path dir) throws Exception {
    byte[] bytes =
        "2D-Map\nCairn: Goal 1 2 0 \"\" ICON \"Se\u00f1or\"\nDATA\n"
            .getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
    Path in = Files.write(dir.resolve("in.map"), bytes);
    ArMap m = ArMap.readFile(in);
    assertEquals("Se\u00f1or", m.getMapObjects().get(0).name());
    Path out = dir.resolve("out.map");
    m.writeFile(out);
    assertArrayEquals(bytes, Files.readAllBytes(out));
  }
}
