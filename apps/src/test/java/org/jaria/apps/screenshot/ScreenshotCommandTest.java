package org.jaria.apps.screenshot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.RgbImage;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.testfx.framework.junit5.ApplicationExtension;
import picocli.CommandLine;

/** {@code jaria screenshot} renders each app to a PNG without a display. */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class ScreenshotCommandTest {

  @TempDir Path dir;

  private final StringWriter out = new StringWriter();
  private final StringWriter err = new StringWriter();

  private int run(String... args) {
    CommandLine cl = new CommandLine(new ScreenshotCommand());
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    return cl.execute(args);
  }

  private static int colours(RgbImage img) {
    Set<Integer> c = new HashSet<>();
    for (int p : img.pixels()) {
      c.add(p);
    }
    return c.size();
  }

  /** The README's line: {@code ./jaria screenshot mapper columbia -o mapper.png}. */
  @Test
  void mapperWithTheBundledColumbiaMap() throws Exception {
    Path png = dir.resolve("mapper.png");
    assertEquals(
        0, run("mapper", "columbia", "-o", png.toString(), "--size", "800x600"), err::toString);
    assertTrue(out.toString().contains("wrote"), out::toString);
    RgbImage img = ImageFiles.read(png);
    assertEquals(800, img.width());
    assertEquals(600, img.height());
    assertTrue(colours(img) > 20, "a drawn window, not a blank one");
  }

  @Test
  void eztrainInThreshViewAndSimview() throws Exception {
    Path a = dir.resolve("ez.png");
    assertEquals(
        0,
        run(
            "eztrain",
            "--train",
            "30,67,70,75",
            "--view",
            "thresh",
            "-o",
            a.toString(),
            "--size",
            "900x600"),
        err::toString);
    assertEquals(900, ImageFiles.read(a).width());
    Path b = dir.resolve("sim.png");
    assertEquals(
        0, run("simview", "--map", "hall", "--advance", "500", "-o", b.toString()), err::toString);
    assertEquals(1280, ImageFiles.read(b).width());
  }

  @Test
  void errorsSayWhatIsWrong() {
    Path png = dir.resolve("x.png");
    assertEquals(2, run("paint", "-o", png.toString()));
    assertTrue(err.toString().contains("no app 'paint'"), err::toString);
    assertEquals(2, run("mapper", "-o", png.toString(), "--size", "big"));
    assertTrue(err.toString().contains("--size"), err::toString);
    assertEquals(1, run("mapper", dir.resolve("missing.map").toString(), "-o", png.toString()));
    assertTrue(err.toString().contains("no map file"), err::toString);
    assertTrue(err.toString().contains("bundled: office, hall, columbia"), err::toString);
    assertFalse(Files.exists(png));
  }
}
