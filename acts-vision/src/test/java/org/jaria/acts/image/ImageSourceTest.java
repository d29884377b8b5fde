package org.jaria.acts.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.acts.testing.Pictures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ImageSourceTest {

  @TempDir Path dir;

  @Test
  void stillImageIsScaledOnceAndRepeated() throws IOException {
    Path f = dir.resolve("test.ppm");
    ImageFiles.write(TestScene.render(), f);
    try (StillImageSource s = StillImageSource.open(f, 160, 120)) {
      assertEquals(160, s.width());
      int[] a = new int[160 * 120];
      int[] b = new int[160 * 120];
      assertTrue(s.nextFrame(a));
      assertTrue(s.nextFrame(b));
      assertEquals(java.util.Arrays.hashCode(a), java.util.Arrays.hashCode(b));
      assertTrue(new RgbImage(160, 120, a).samePixels(TestScene.render(160, 120)));
      byte[] bytes = new byte[3 * 160 * 120];
      assertTrue(s.nextFrame(bytes));
      assertEquals((byte) (a[0] >>> 16), bytes[0]);
      assertTrue(s.describe().contains("test.ppm 160x120"), s.describe());
    }
  }

  @Test
  void sequencePlaysAFolderInNameOrder() throws IOException {
    ImageFiles.write(Pictures.draw("RR"), dir.resolve("b.png"));
    ImageFiles.write(Pictures.draw("GG"), dir.resolve("a.ppm"));
    Files.writeString(dir.resolve("notes.txt"), "not an image");
    ImageSequenceSource s = ImageSequenceSource.ofDirectory(dir, 2, 1, false);
    assertEquals(2, s.files().size());
    int[] px = new int[2];
    assertTrue(s.nextFrame(px));
    assertEquals(Pictures.GREEN, px[0]);
    assertTrue(s.nextFrame(px));
    assertEquals(Pictures.RED, px[0]);
    assertFalse(s.nextFrame(px), "no more frames");

    ImageSequenceSource loop = new ImageSequenceSource(s.files(), 4, 2, true);
    int[] big = new int[8];
    for (int i = 0; i < 5; i++) {
      assertTrue(loop.nextFrame(big));
    }
    assertEquals(Pictures.GREEN, big[7], "5th frame is the first file again, scaled");
  }

  @Test
  void emptyFolderIsAnError() throws IOException {
    Path empty = Files.createDirectory(dir.resolve("empty"));
    IOException e =
        assertThrows(IOException.class, () -> ImageSequenceSource.ofDirectory(empty, 2, 2, true));
    assertTrue(e.getMessage().contains("holds no image files"), e.getMessage());
    assertThrows(
        IllegalArgumentException.class, () -> new ImageSequenceSource(List.of(), 2, 2, true));
  }
}
