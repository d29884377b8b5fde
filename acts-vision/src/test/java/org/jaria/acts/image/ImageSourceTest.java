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
import org.opencv.core.CvType;
import org.opencv.core.Mat;
import org.opencv.core.Point;
import org.opencv.core.Scalar;
import org.opencv.core.Size;
import org.opencv.imgproc.Imgproc;
import org.opencv.videoio.VideoWriter;

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

  @Test
  void aMissingCameraGivesAClearMessage() {
    // CI machines have no camera; index 99 does not exist on developer machines either.
    IOException e = assertThrows(IOException.class, () -> CameraSource.open("99", 160, 120));
    assertTrue(e.getMessage().contains("no camera found at device index 99"), e.getMessage());
    assertTrue(e.getMessage().contains("-f FILE"), e.getMessage());
  }

  @Test
  void aMissingDevicePathGivesAClearMessage() {
    String p = dir.resolve("video7").toString();
    IOException e = assertThrows(IOException.class, () -> CameraSource.open(p, 160, 120));
    assertTrue(e.getMessage().contains("no camera or video file at '" + p + "'"), e.getMessage());
  }

  @Test
  void anUnreadableVideoFileGivesAClearMessage() throws IOException {
    Path f = dir.resolve("broken.avi");
    Files.writeString(f, "not a video");
    IOException e =
        assertThrows(IOException.class, () -> CameraSource.open(f.toString(), 160, 120));
    assertTrue(e.getMessage().contains("could not open"), e.getMessage());
  }

  @Test
  void cameraParametersAreListed() {
    String list = CameraSource.parameterList();
    assertTrue(list.contains("brightness"));
    assertTrue(list.contains("contrast"));
    assertTrue(CameraSource.PARAMETERS.containsKey("exposure"));
  }

  @Test
  void aVideoFileIsReadThroughTheCameraPath() throws Exception {
    // The live-camera code (OpenCV's VideoCapture) on a video OpenCV itself wrote: a red square
    // moving right across a grey field, 10 frames.
    OpenCvLoader.load();
    Path file = dir.resolve("square.avi");
    VideoWriter writer =
        new VideoWriter(
            file.toString(), VideoWriter.fourcc('M', 'J', 'P', 'G'), 10, new Size(160, 120));
    assertTrue(writer.isOpened(), "OpenCV can write MJPG video here");
    for (int k = 0; k < 10; k++) {
      Mat frame = new Mat(120, 160, CvType.CV_8UC3, new Scalar(90, 90, 90));
      Imgproc.rectangle(
          frame,
          new Point(10 + 10 * k, 40),
          new Point(40 + 10 * k, 70),
          new Scalar(0, 0, 255), // BGR: red
          -1);
      writer.write(frame);
      frame.release();
    }
    writer.release();

    try (CameraSource cam = CameraSource.open(file.toString(), 160, 120)) {
      int[] rgb = new int[160 * 120];
      double firstX = Double.NaN;
      double lastX = Double.NaN;
      int frames = 0;
      while (frames < 10 && cam.nextFrame(rgb)) {
        long sum = 0;
        int n = 0;
        for (int i = 0; i < rgb.length; i++) {
          int r = (rgb[i] >> 16) & 0xFF;
          int g = (rgb[i] >> 8) & 0xFF;
          if (r > 180 && g < 90) {
            sum += i % 160;
            n++;
          }
        }
        assertTrue(n > 500, "frame " + frames + " shows the red square (" + n + " px)");
        double x = (double) sum / n;
        firstX = frames == 0 ? x : firstX;
        lastX = x;
        frames++;
      }
      assertEquals(10, frames, "every frame of the video was read");
      assertEquals(90, lastX - firstX, 6, "the square moved 90 px right, in RGB order");
    }
  }
}
