package org.jaria.apps.eztrain;

import java.nio.file.Path;
import java.util.List;

/**
 * How EZ-Train starts (from its command line).
 *
 * @param config runtime configuration to load, or null
 * @param image still image to train on, or null for the tutorial image (unless a camera is given)
 * @param device camera to start with (index or path), or null
 * @param port ACTS server port (0 = any free port, -1 = no server)
 * @param width working image width
 * @param height working image height
 * @param minBlobSize minimum blob width and height, pixels
 * @param maxFps the server's frame rate limit
 * @param view the view mode to start in
 * @param channel the channel selected at start
 * @param train rectangles {x0, y0, x1, y1} to Add to that channel at start (scripting, screenshots)
 * @param magnification 1..6
 * @param baseDir where relative channel file names live
 * @param blobStats whether to print the blob stats once the first image is shown
 * @param simCamera whether to start with live video from the simulator's camera
 * @param simPort the TCP port of the simulated robot behind that camera (0: any free port; -1:
 *     none)
 */
public record EzTrainOptions(
    Path config,
    Path image,
    String device,
    int port,
    int width,
    int height,
    int minBlobSize,
    int maxFps,
    ViewMode view,
    int channel,
    List<int[]> train,
    int magnification,
    Path baseDir,
    boolean blobStats,
    boolean simCamera,
    int simPort) {

  /** Copies the list. */
  public EzTrainOptions {
    train = List.copyOf(train);
    if (baseDir == null) {
      baseDir = Path.of("");
    }
  }

  /** ACTS's defaults: tutorial image, 160×120, server on port 5001, Overlay view, channel 1. */
  public static EzTrainOptions defaults() {
    return new EzTrainOptions(
        null,
        null,
        null,
        5001,
        160,
        120,
        5,
        30,
        ViewMode.OVERLAY,
        1,
        List.of(),
        3,
        Path.of(""),
        false,
        false,
        8101);
  }

  /** These options with another server port (0: any free port, -1: no server). */
  public EzTrainOptions withPort(int p) {
    return new EzTrainOptions(
        config,
        image,
        device,
        p,
        width,
        height,
        minBlobSize,
        maxFps,
        view,
        channel,
        train,
        magnification,
        baseDir,
        blobStats,
        simCamera,
        simPort);
  }

  /** These options with another image file. */
  public EzTrainOptions withImage(Path file) {
    return new EzTrainOptions(
        config,
        file,
        device,
        port,
        width,
        height,
        minBlobSize,
        maxFps,
        view,
        channel,
        train,
        magnification,
        baseDir,
        blobStats,
        simCamera,
        simPort);
  }

  /** These options with another folder for channel files. */
  public EzTrainOptions withBaseDir(Path dir) {
    return new EzTrainOptions(
        config,
        image,
        device,
        port,
        width,
        height,
        minBlobSize,
        maxFps,
        view,
        channel,
        train,
        magnification,
        dir,
        blobStats,
        simCamera,
        simPort);
  }

  /**
   * These options starting (or not) on the simulator's camera, its robot on TCP port {@code port}
   * (0: any free port; -1: none).
   */
  public EzTrainOptions withSimCamera(boolean on, int port) {
    return new EzTrainOptions(
        config,
        image,
        device,
        this.port,
        width,
        height,
        minBlobSize,
        maxFps,
        view,
        channel,
        train,
        magnification,
        baseDir,
        blobStats,
        on,
        port);
  }
}
