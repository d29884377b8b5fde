package org.jaria.acts.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.jaria.acts.ActsFormatException;
import org.jaria.acts.testing.Pictures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ImageFilesTest {

  @TempDir Path dir;

  @Test
  void binaryPpmRoundTrip() throws IOException {
    RgbImage img = Pictures.randomShapes(37, 23, 3);
    Path f = dir.resolve("a.ppm");
    ImageFiles.write(img, f);
    assertTrue(new String(Files.readAllBytes(f), 0, 2, StandardCharsets.US_ASCII).equals("P6"));
    assertTrue(ImageFiles.read(f).samePixels(img));
  }

  @Test
  void pngRoundTripIsLossless() throws IOException {
    RgbImage img = Pictures.noise(40, 30, 4);
    Path f = dir.resolve("a.png");
    ImageFiles.write(img, f);
    assertTrue(ImageFiles.read(f).samePixels(img));
  }

  @Test
  void jpegIsReadApproximately() throws IOException {
    RgbImage img = new RgbImage(16, 16);
    Arrays.fill(img.pixels(), RgbImage.pack(200, 40, 30));
    Path f = dir.resolve("a.jpg");
    ImageFiles.write(img, f);
    RgbImage back = ImageFiles.read(f);
    int p = back.get(8, 8);
    assertEquals(200, (p >>> 16) & 0xFF, 8);
    assertEquals(40, (p >>> 8) & 0xFF, 8);
  }

  @Test
  void textPpmWithCommentsAndSixteenBitSamples() throws IOException {
    String p3 = "P3\n# a comment\n2 1 # inline\n65535\n65535 0 0   0 32768 65535\n";
    RgbImage img = ImageFiles.read(p3.getBytes(StandardCharsets.US_ASCII), "t.ppm");
    assertEquals(2, img.width());
    assertEquals(0xFF0000, img.get(0, 0));
    assertEquals(RgbImage.pack(0, 128, 255), img.get(1, 0));
    byte[] p6 = {
      'P',
      '6',
      ' ',
      '1',
      ' ',
      '1',
      ' ',
      '6',
      '5',
      '5',
      '3',
      '5',
      '\n',
      (byte) 0xFF,
      (byte) 0xFF,
      0,
      0,
      (byte) 0x80,
      0
    };
    assertEquals(RgbImage.pack(255, 0, 128), ImageFiles.read(p6, "s.ppm").get(0, 0));
  }

  @Test
  void damagedPpmGivesClearErrors() {
    assertError("P6\n4 4\n255\n" + "x".repeat(10), "truncated");
    assertError("P6\n4\n", "truncated");
    assertError("P3\n1 1\n255\n1 2 300\n", "too large");
    assertError("P6\n0 4\n255\n", "image size");
    assertError("P6\n4 4\n0\n", "maximum sample value");
    assertError("P6\n99999 99999\n255\n", "image size");
    assertError("hello", "not an image");
  }

  private static void assertError(String content, String expected) {
    ActsFormatException e =
        assertThrows(
            ActsFormatException.class,
            () -> ImageFiles.read(content.getBytes(StandardCharsets.ISO_8859_1), "bad.ppm"));
    assertTrue(e.getMessage().startsWith("bad.ppm"), e.getMessage());
    assertTrue(e.getMessage().contains(expected), e.getMessage());
  }

  @Test
  void fuzzedPpmNeverCrashes() {
    byte[] good = ImageFiles.toPpm(Pictures.randomShapes(20, 10, 1));
    SplittableRandom r = new SplittableRandom(11);
    for (int i = 0; i < 2000; i++) {
      byte[] b = Arrays.copyOf(good, r.nextInt(2, good.length + 5));
      for (int k = 0; k < r.nextInt(4); k++) {
        b[r.nextInt(Math.min(b.length, 20))] = (byte) r.nextInt(256);
      }
      b[0] = 'P';
      b[1] = r.nextBoolean() ? (byte) '6' : (byte) '3';
      try {
        RgbImage img = ImageFiles.read(b, "fuzz.ppm");
        assertTrue(img.width() > 0 && img.height() > 0);
      } catch (ActsFormatException e) {
        assertTrue(e.getMessage().startsWith("fuzz.ppm"), e.getMessage());
      } catch (IOException e) {
        throw new AssertionError("unexpected " + e, e);
      }
    }
  }

  @Test
  void missingFileAndUnknownExtension() {
    IOException e = assertThrows(IOException.class, () -> ImageFiles.read(dir.resolve("no.ppm")));
    assertTrue(e.getMessage().contains("no such image file"), e.getMessage());
    assertThrows(
        IOException.class, () -> ImageFiles.write(new RgbImage(1, 1), dir.resolve("a.tiff")));
  }

  @Test
  void scalingAveragesWhenShrinkingAndIsIdentityAtTheSameSize() {
    RgbImage img = Pictures.draw("RRBB", "RRBB");
    RgbImage half = img.scaled(2, 1);
    assertEquals(Pictures.RED, half.get(0, 0));
    assertEquals(Pictures.BLUE, half.get(1, 0));
    RgbImage mixed = Pictures.draw("RB").scaled(1, 1);
    assertEquals(RgbImage.pack(128, 0, 128), mixed.get(0, 0));
    assertTrue(img.scaled(4, 2) == img);
    RgbImage big = Pictures.draw("R").scaled(3, 3);
    assertEquals(Pictures.RED, big.get(2, 2));
    RgbImage scene = TestScene.render();
    RgbImage small = scene.scaled(160, 120);
    assertEquals(160, small.width());
    assertEquals(120, small.height());
  }

  @Test
  void rotationAndByteConversion() {
    RgbImage img = Pictures.draw("RG", "B.");
    RgbImage rot = img.rotated180();
    assertEquals(0, rot.get(0, 0));
    assertEquals(Pictures.RED, rot.get(1, 1));
    byte[] bytes = img.toRgbBytes();
    assertEquals((byte) 255, bytes[0]);
    assertEquals((byte) 255, bytes[4]);
    int[] back = new int[4];
    RgbImage.fromRgbBytes(bytes, back);
    assertTrue(new RgbImage(2, 2, back).samePixels(img));
  }
}
