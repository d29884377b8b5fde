package org.jaria.acts.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TestSceneTest {

  @Test
  void shippedCopiesAreTheGeneratedScene() throws IOException {
    RgbImage scene = TestScene.render();
    assertTrue(TestScene.load().samePixels(scene), "desk-scene.ppm is stale: run TestScene.main");
    try (InputStream in = TestScene.class.getResourceAsStream(TestScene.PNG_RESOURCE)) {
      assertNotNull(in);
      assertTrue(ImageFiles.read(in, "png").samePixels(scene), "desk-scene.png is stale");
    }
  }

  @Test
  void renderingIsDeterministic() {
    assertTrue(TestScene.render().samePixels(TestScene.render()));
    assertEquals(160, TestScene.render(160, 120).width());
  }

  @Test
  void landmarksAreRed() {
    RgbImage scene = TestScene.render();
    for (TestScene.Box b : new TestScene.Box[] {TestScene.BOOK, TestScene.CUP}) {
      for (int y = b.y0(); y <= b.y1(); y++) {
        for (int x = b.x0(); x <= b.x1(); x++) {
          int p = scene.get(x, y);
          int r = (p >>> 16) & 0xFF;
          int g = (p >>> 8) & 0xFF;
          int bl = p & 0xFF;
          assertTrue(
              r > 120 && g < 60 && bl < 70,
              "not red at " + x + "," + y + ": " + r + " " + g + " " + bl);
        }
      }
    }
  }

  @Test
  void mainWritesBothFiles(@TempDir Path dir) throws IOException {
    TestScene.main(new String[] {dir.toString()});
    assertTrue(ImageFiles.read(dir.resolve("desk-scene.ppm")).samePixels(TestScene.render()));
    assertTrue(Files.size(dir.resolve("desk-scene.png")) > 1000);
  }

  /**
   * {@code acts -f desk-scene} and {@code eztrain -f desk-scene} (README) mean the shipped scene.
   */
  @Test
  void theShippedSceneHasANameTheCommandsAccept() {
    assertTrue(TestScene.isBundledName(Path.of("desk-scene")));
    assertTrue(TestScene.isBundledName(Path.of("desk-scene.ppm")));
    assertTrue(!TestScene.isBundledName(Path.of("desk.ppm")), "another name is a file name");
    assertTrue(!TestScene.isBundledName(Path.of("/nowhere/desk-scene")), "a path is a file");
  }
}
