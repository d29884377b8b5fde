package org.jaria.acts.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.jaria.acts.blob.BlobTracker;
import org.jaria.acts.blob.ChannelComponents;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.image.TestScene;
import org.jaria.acts.testing.Pictures;
import org.jaria.acts.testing.SceneChannels;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.opencv.core.Core;
import org.opencv.core.CvType;
import org.opencv.core.Mat;
import org.opencv.core.Scalar;
import org.opencv.imgproc.Imgproc;

/**
 * The tracker's regions against OpenCV's {@code connectedComponentsWithStats} with 4-connectivity
 * (CMVision merges runs that overlap on adjacent rows, which is 4-connectivity) on the same pixel
 * set: {@code inRange} with the channel's RGB box, or, for a channel trained by hand, the tracker's
 * own classification mask. Labels must induce the same partition of the pixels, and areas, bounding
 * boxes and centroids must be equal.
 */
class OpenCvCrossCheckTest {

  @BeforeAll
  static void loadOpenCv() throws IOException {
    OpenCvLoader.load();
  }

  @Test
  void randomShapesAndBoxesAgree() {
    SplittableRandom r = new SplittableRandom(77);
    for (int i = 0; i < 25; i++) {
      int w = 20 + r.nextInt(200);
      int h = 10 + r.nextInt(150);
      RgbImage img = Pictures.randomShapes(w, h, r.nextLong());
      int r0 = r.nextInt(200);
      int g0 = r.nextInt(200);
      int b0 = r.nextInt(200);
      int[] box = {
        r0,
        r0 + r.nextInt(56, 256 - r0),
        g0,
        g0 + r.nextInt(56, 256 - g0),
        b0,
        b0 + r.nextInt(56, 256 - b0)
      };
      compareBox(img, box);
    }
  }

  @Test
  void noiseAgrees() {
    // About half of all pixels in the channel: a maze of tiny regions, one run per few pixels.
    compareBox(Pictures.noise(320, 240, 5), new int[] {0, 255, 0, 127, 0, 255});
    compareBox(Pictures.noise(160, 120, 6), new int[] {0, 200, 40, 255, 0, 230});
  }

  @Test
  void deskSceneWithBoxChannelsAgrees() {
    RgbImage scene = TestScene.render();
    for (int i = 0; i < 8; i++) {
      compareBox(scene, SceneChannels.box(i));
    }
    compareBox(TestScene.render(640, 480), SceneChannels.box(0));
  }

  @Test
  void deskSceneWithAHandTrainedChannelAgrees() {
    RgbImage scene = TestScene.render();
    ChannelBank bank = new ChannelBank();
    Trainer t = new Trainer(bank);
    t.addRect(
        scene, TestScene.BOOK.x0(), TestScene.BOOK.y0(), TestScene.BOOK.x1(), TestScene.BOOK.y1());
    t.removeRect(scene, 0, 0, 40, 40); // some wall colours out, whatever they were
    LookupTables tables = bank.tables();
    byte[] mask = new byte[scene.pixels().length];
    for (int i = 0; i < mask.length; i++) {
      mask[i] = (byte) ((tables.classify(scene.pixels()[i]) & 1) != 0 ? 255 : 0);
    }
    Mat binary = new Mat(scene.height(), scene.width(), CvType.CV_8UC1);
    binary.put(0, 0, mask);
    compare(scene, tables, 1, binary);
  }

  @Test
  void aRealPhotographAgreesAtFullAndWorkingSize() throws IOException {
    RgbImage photo;
    try (java.io.InputStream in =
        OpenCvCrossCheckTest.class.getResourceAsStream("/org/jaria/acts/photos/fruits.jpg")) {
      photo = org.jaria.acts.image.ImageFiles.read(in, "fruits.jpg");
    }
    assertEquals(512, photo.width());
    // Red apples; the orange; the yellow bananas; and a loose box that takes in half the picture.
    int[][] boxes = {
      {150, 255, 0, 90, 0, 90},
      {200, 255, 90, 180, 0, 80},
      {180, 255, 170, 255, 0, 120},
      {0, 160, 0, 255, 0, 255}
    };
    ChannelBank red = new ChannelBank();
    Pictures.box(red, 1, 150, 255, 0, 90, 0, 90);
    ChannelComponents apples = new ChannelComponents();
    new BlobTracker()
        .components(
            photo.pixels(),
            photo.width(),
            photo.height(),
            red.tables(),
            1,
            apples,
            new int[photo.pixels().length]);
    assertTrue(apples.count() > 0, "the photo has red regions to compare");
    for (int[] box : boxes) {
      compareBox(photo, box);
      compareBox(photo.scaled(160, 120), box);
    }
    // The same with a channel trained by hand on an apple, as EZ-Train would.
    ChannelBank bank = new ChannelBank();
    new Trainer(bank).addRect(photo, 60, 330, 120, 400);
    LookupTables tables = bank.tables();
    byte[] mask = new byte[photo.pixels().length];
    for (int i = 0; i < mask.length; i++) {
      mask[i] = (byte) ((tables.classify(photo.pixels()[i]) & 1) != 0 ? 255 : 0);
    }
    Mat binary = new Mat(photo.height(), photo.width(), CvType.CV_8UC1);
    binary.put(0, 0, mask);
    compare(photo, tables, 1, binary);
  }

  private static void compareBox(RgbImage img, int[] box) {
    ChannelBank bank = new ChannelBank();
    Pictures.box(bank, 1, box[0], box[1], box[2], box[3], box[4], box[5]);
    Mat rgb = new Mat(img.height(), img.width(), CvType.CV_8UC3);
    rgb.put(0, 0, img.toRgbBytes());
    Mat binary = new Mat();
    Core.inRange(
        rgb, new Scalar(box[0], box[2], box[4]), new Scalar(box[1], box[3], box[5]), binary);
    compare(img, bank.tables(), 1, binary);
    rgb.release();
  }

  private static void compare(RgbImage img, LookupTables tables, int channel, Mat binary) {
    int w = img.width();
    int h = img.height();
    Mat labels = new Mat();
    Mat stats = new Mat();
    Mat centroids = new Mat();
    int n =
        Imgproc.connectedComponentsWithStats(binary, labels, stats, centroids, 4, CvType.CV_32S);
    int[] cvLabels = new int[w * h];
    labels.get(0, 0, cvLabels);

    ChannelComponents ours = new ChannelComponents();
    int[] ourLabels = new int[w * h];
    new BlobTracker().components(img.pixels(), w, h, tables, channel, ours, ourLabels);

    assertEquals(n - 1, ours.count(), "component count (OpenCV counts the background too)");
    Map<Integer, Integer> map = new HashMap<>();
    for (int i = 0; i < w * h; i++) {
      assertEquals(cvLabels[i] == 0, ourLabels[i] == 0, "same pixel set at " + i);
      if (ourLabels[i] != 0) {
        Integer prev = map.putIfAbsent(ourLabels[i], cvLabels[i]);
        assertTrue(prev == null || prev == cvLabels[i], "same partition at pixel " + i);
      }
    }
    assertEquals(ours.count(), map.size());
    assertEquals(ours.count(), map.values().stream().distinct().count(), "one to one");
    int[] s = new int[5];
    double[] c = new double[2];
    for (var e : map.entrySet()) {
      int i = e.getKey() - 1;
      int k = e.getValue();
      stats.get(k, 0, s);
      centroids.get(k, 0, c);
      assertEquals(s[Imgproc.CC_STAT_AREA], ours.area(i));
      assertEquals(s[Imgproc.CC_STAT_LEFT], ours.left(i));
      assertEquals(s[Imgproc.CC_STAT_TOP], ours.top(i));
      assertEquals(s[Imgproc.CC_STAT_LEFT] + s[Imgproc.CC_STAT_WIDTH] - 1, ours.right(i));
      assertEquals(s[Imgproc.CC_STAT_TOP] + s[Imgproc.CC_STAT_HEIGHT] - 1, ours.bottom(i));
      assertEquals(c[0], ours.xCentroid(i), 1e-9);
      assertEquals(c[1], ours.yCentroid(i), 1e-9);
    }
    labels.release();
    stats.release();
    centroids.release();
    binary.release();
  }
}
