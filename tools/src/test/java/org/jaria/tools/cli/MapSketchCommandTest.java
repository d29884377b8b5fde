package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jaria.map.ArMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code jaria map sketch}: the sonar sketch of a seeded wander, as a map and a picture. */
class MapSketchCommandTest {

  private record Run(int exit, String out) {}

  private static Run run(String... args) {
    StringWriter out = new StringWriter();
    CommandLine cl = JariaCli.commandLine();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(out));
    return new Run(cl.execute(args), out.toString());
  }

  @Test
  void sketchesTheHallAsPointsAndAPicture(@TempDir Path dir) throws Exception {
    Path map = dir.resolve("hall-sketch.map");
    Path png = dir.resolve("hall-sketch.png");
    Run r =
        run(
            "map",
            "sketch",
            "--sim",
            "hall",
            "--seconds",
            "60",
            "--seed",
            "3",
            "-o",
            map.toString(),
            "-o",
            png.toString());
    assertEquals(0, r.exit(), r.out());
    assertTrue(r.out().contains("do not localize on it"), r.out());
    ArMap m = ArMap.readFile(map);
    assertTrue(m.getPoints().size() > 50, "points: " + m.getPoints().size());
    assertEquals(0, m.getLines().size());
    assertTrue(Files.readString(map).contains("not a map for localization"));
    BufferedImage img = ImageIO.read(png.toFile());
    assertTrue(img.getWidth() > 100 && img.getHeight() > 100);
    assertEquals(0xB00020, img.getRGB(1, 1) & 0xFFFFFF, "the red label band");
  }

  @Test
  void mistakesAreSaid(@TempDir Path dir) {
    Run none = run("map", "sketch", "--sim", "hall", "-o", dir.resolve("x.txt").toString());
    assertEquals(2, none.exit());
    assertTrue(none.out().contains("written as .map or .png"), none.out());
    Run both =
        run(
            "map",
            "sketch",
            "--sim",
            "hall",
            "--remote",
            "x",
            "-o",
            dir.resolve("x.map").toString());
    assertEquals(2, both.exit());
    Run time =
        run(
            "map",
            "sketch",
            "--sim",
            "hall",
            "--seconds",
            "-1",
            "-o",
            dir.resolve("x.map").toString());
    assertEquals(2, time.exit());
    Run noMap =
        run(
            "map",
            "sketch",
            "--sim",
            dir.resolve("none.map").toString(),
            "-o",
            dir.resolve("x.map").toString());
    assertEquals(1, noMap.exit(), noMap.out());
    assertFalse(Files.exists(dir.resolve("x.map")), "nothing written");
  }
}
