package org.jaria.apps.bench;

import java.io.IOException;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.blob.BlobTracker;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.camera.OpenCvLoader;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.image.StillImageSource;
import org.jaria.acts.image.TestScene;
import org.jaria.acts.server.ActsServer;
import org.jaria.acts.server.ServerSettings;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.acts.testing.SceneChannels;
import org.jaria.clock.Clock;
import org.opencv.core.Core;
import org.opencv.core.CvType;
import org.opencv.core.Mat;
import org.opencv.core.Scalar;
import org.opencv.imgproc.Imgproc;

/**
 * How fast the tracker is, on one core, against OpenCV doing the same work.
 *
 * <ul>
 *   <li>JAria: classification of every channel at once, run-length encoding, union-find merging of
 *       runs and blob statistics ({@link BlobTracker#track}) on the desk test scene at 160×120,
 *       320×240 and 640×480 with 1, 8 and 32 trained channels (RGB boxes around the scene's objects
 *       and variations of them).
 *   <li>OpenCV: for each channel one {@code inRange} with the same box and one {@code
 *       connectedComponentsWithStats} (4-connectivity), single-threaded ({@code
 *       Core.setNumThreads(1)}); the frame is already in a {@code Mat}, so no conversion is
 *       counted.
 *   <li>The plane resolution trade-off: 640×480, 8 channels, with 8-, 7- and 6-bit cells, on the
 *       scene and on uniform noise.
 *   <li>The ACTS server round trip on loopback: {@code requestPacket()} to the last byte of the
 *       reply received by {@link ArACTS_1_2#receiveBlobInfo()}.
 * </ul>
 *
 * <p>Each figure is the median of several timed rounds after a warm-up.
 */
public final class VisionBenchmark {

  private VisionBenchmark() {}

  /**
   * How long the benchmark runs: each figure's rounds take about {@code budgetNanos} each, and the
   * round trip is timed {@code samples} times.
   */
  record Effort(String name, long budgetNanos, int rounds, int samples) {
    static final Effort FULL = new Effort("full", 400_000_000L, 7, 5000);
    static final Effort QUICK = new Effort("quick", 40_000_000L, 3, 500);
  }

  /** Runs everything and returns the table ({@code quick}: shorter, less precise runs). */
  public static String run(boolean quick) throws IOException, InterruptedException {
    return run(quick ? Effort.QUICK : Effort.FULL);
  }

  /** Runs everything with that effort and returns the table. */
  static String run(Effort effort) throws IOException, InterruptedException {
    OpenCvLoader.load();
    Core.setNumThreads(1);
    long budget = effort.budgetNanos();
    int rounds = effort.rounds();
    StringBuilder out = new StringBuilder();
    out.append("JAria ACTS vision benchmark (")
        .append(effort.name())
        .append("), one core, desk test scene, median of ")
        .append(rounds)
        .append(" rounds\n");
    out.append(
        String.format(
            Locale.ROOT,
            "%-9s %4s | %10s %11s | %10s %11s | %7s%n",
            "size",
            "ch",
            "JAria ms",
            "JAria fps",
            "OpenCV ms",
            "OpenCV fps",
            "speedup"));
    int[][] sizes = {{160, 120}, {320, 240}, {640, 480}};
    int[] channelCounts = {1, 8, 32};
    for (int[] s : sizes) {
      RgbImage img = TestScene.render(s[0], s[1]);
      for (int n : channelCounts) {
        double ours =
            timeTracker(img, SceneChannels.bank(n, ChannelBank.DEFAULT_CELL_BITS), budget, rounds);
        double cv = timeOpenCv(img, n, budget, rounds);
        out.append(
            String.format(
                Locale.ROOT,
                "%-9s %4d | %10.4f %11.0f | %10.4f %11.0f | %6.1fx%n",
                s[0] + "x" + s[1],
                n,
                ours / 1e6,
                1e9 / ours,
                cv / 1e6,
                1e9 / cv,
                cv / ours));
      }
    }
    out.append("\nPlane resolution, 640x480, 8 channels (ms per frame):\n");
    out.append(String.format(Locale.ROOT, "%-10s %12s %12s%n", "cells", "scene", "noise"));
    RgbImage scene = TestScene.render(640, 480);
    RgbImage noise = noise(640, 480, 42);
    for (int bits = 8; bits >= 6; bits--) {
      ChannelBank bank = SceneChannels.bank(8, bits);
      double a = timeTracker(scene, bank, budget, rounds);
      double b = timeTracker(noise, bank, budget, rounds);
      out.append(
          String.format(
              Locale.ROOT,
              "%-10s %12.4f %12.4f%n",
              (1 << bits) + "x" + (1 << bits),
              a / 1e6,
              b / 1e6));
    }
    out.append(roundTrip(effort.samples()));
    return out.toString();
  }

  /** Uniformly random pixels (the worst case for runs and caches). */
  public static RgbImage noise(int w, int h, long seed) {
    java.util.SplittableRandom r = new java.util.SplittableRandom(seed);
    int[] px = new int[w * h];
    for (int i = 0; i < px.length; i++) {
      px[i] = r.nextInt(1 << 24);
    }
    return new RgbImage(w, h, px);
  }

  private static double timeTracker(RgbImage img, ChannelBank bank, long budget, int rounds) {
    BlobTracker tracker = new BlobTracker();
    BlobFrame frame = new BlobFrame();
    LookupTables tables = bank.tables();
    int[] px = img.pixels();
    int w = img.width();
    int h = img.height();
    TrackerSettings settings = TrackerSettings.DEFAULT;
    Runnable step = () -> tracker.track(px, w, h, tables, settings, frame);
    return medianNanos(step, budget, rounds);
  }

  private static double timeOpenCv(RgbImage img, int n, long budget, int rounds) {
    Mat mat = new Mat(img.height(), img.width(), CvType.CV_8UC3);
    mat.put(0, 0, img.toRgbBytes());
    Mat mask = new Mat();
    Mat labels = new Mat();
    Mat stats = new Mat();
    Mat centroids = new Mat();
    Scalar[] lo = new Scalar[n];
    Scalar[] hi = new Scalar[n];
    for (int i = 0; i < n; i++) {
      int[] b = SceneChannels.box(i);
      lo[i] = new Scalar(b[0], b[2], b[4]);
      hi[i] = new Scalar(b[1], b[3], b[5]);
    }
    Runnable step =
        () -> {
          for (int i = 0; i < n; i++) {
            Core.inRange(mat, lo[i], hi[i], mask);
            Imgproc.connectedComponentsWithStats(mask, labels, stats, centroids, 4, CvType.CV_32S);
          }
        };
    try {
      return medianNanos(step, budget, rounds);
    } finally {
      mat.release();
      mask.release();
      labels.release();
      stats.release();
      centroids.release();
    }
  }

  // Warms up for one budget, then times `rounds` batches of about one budget each.
  private static double medianNanos(Runnable step, long budget, int rounds) {
    long t0 = System.nanoTime();
    int calls = 0;
    while (System.nanoTime() - t0 < budget || calls < 3) {
      step.run();
      calls++;
    }
    int batch = Math.max(1, calls);
    double[] perCall = new double[rounds];
    for (int r = 0; r < rounds; r++) {
      long s = System.nanoTime();
      for (int i = 0; i < batch; i++) {
        step.run();
      }
      perCall[r] = (double) (System.nanoTime() - s) / batch;
    }
    Arrays.sort(perCall);
    return perCall[rounds / 2];
  }

  private static String roundTrip(int samples) throws IOException, InterruptedException {
    StillImageSource src = new StillImageSource(TestScene.render(160, 120));
    VisionPipeline pipeline =
        new VisionPipeline(src, SceneChannels.bank(8, 8), TrackerSettings.DEFAULT);
    ActsServer server =
        new ActsServer(
            pipeline,
            ServerSettings.DEFAULT.withAddress("127.0.0.1", 0).withMaxFps(30),
            Clock.system());
    server.start();
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      if (!server.awaitFrames(1, 10, TimeUnit.SECONDS)
          || !acts.openPort("127.0.0.1", server.getPort())) {
        return "\nACTS round trip: could not connect (" + acts.getOpenMessage() + ")\n";
      }
      acts.setReadTimeouts(2000, 2000);
      long[] lat = new long[samples];
      int blobs = 0;
      for (int i = -samples / 5; i < samples; i++) {
        long s = System.nanoTime();
        acts.requestPacket();
        if (!acts.receiveBlobInfo()) {
          return "\nACTS round trip: a reply did not arrive\n";
        }
        long d = System.nanoTime() - s;
        if (i >= 0) {
          lat[i] = d;
        }
        blobs = 0;
        for (int c = 1; c <= 32; c++) {
          blobs += acts.getNumBlobs(c);
        }
      }
      Arrays.sort(lat);
      return String.format(
          Locale.ROOT,
          "%nACTS server round trip on loopback (request to last byte, 160x120, 8 channels, %d"
              + " blobs, %d bytes): p50 %.1f us, p90 %.1f us, p99 %.1f us (%d samples)%n",
          blobs,
          ArACTS_1_2.DATA_HEADER + blobs * ArACTS_1_2.ACTS_BLOB_DATA_SIZE,
          lat[samples / 2] / 1e3,
          lat[samples * 9 / 10] / 1e3,
          lat[samples * 99 / 100] / 1e3,
          samples);
    } finally {
      server.stop();
    }
  }

  /** Prints the table ({@code --quick} for shorter runs). */
  public static void main(String[] args) throws Exception {
    boolean quick = Arrays.asList(args).contains("--quick");
    System.out.print(run(quick));
  }
}
