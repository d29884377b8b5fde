package org.jaria.acts.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jaria.acts.image.Cameras;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.opencv.core.CvType;
import org.opencv.core.Mat;
import org.opencv.core.Point;
import org.opencv.core.Scalar;
import org.opencv.core.Size;
import org.opencv.imgproc.Imgproc;
import org.opencv.videoio.VideoWriter;

/** The live camera through OpenCV, on a camera that is not there and on a video file. */
class CameraSourceTest {

  @TempDir Path dir;

  @Test
  void camerasFindThisDriverOnTheClassPath() throws IOException {
    assertInstanceOf(OpenCvCameras.class, Cameras.driver().orElseThrow());
    assertEquals(CameraSource.parameterList(), Cameras.parameterList());
    String p = dir.resolve("video7").toString();
    IOException e = assertThrows(IOException.class, () -> Cameras.open(p, 160, 120));
    assertTrue(e.getMessage().contains("no camera or video file at"), e.getMessage());
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
