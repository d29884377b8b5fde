package org.jaria.apps.eztrain;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import javafx.stage.Stage;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.config.ActsConfig;
import org.jaria.acts.image.TestScene;
import org.jaria.apps.fx.AppCommand;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppLauncher;
import org.jaria.apps.fx.DesktopApp;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria eztrain [-c config] [-f image]}: the EZ-Train colour trainer with the ACTS server
 * running (ACTS's start-up options, thesis table 5.61).
 */
@Command(
    name = "eztrain",
    sortOptions = false,
    description = {
      "EZ-Train: train ACTS color channels on a still image or live video, with the ACTS server"
          + " running (port 5001) so robot programs see the channels as they are trained.",
      "Keys over the image: 1-4 view modes (Overlay, Thresh, Raw, Visible), A Add, R Remove,"
          + " D Draw, E Erase, P Pick; right click cycles the view; Esc quits."
    })
public final class EzTrainCommand implements Callable<Integer>, AppCommand {

  @Spec CommandSpec spec;

  @Option(names = "-c", paramLabel = "CONFIG", description = "Load this runtime configuration.")
  Path config;

  @Option(
      names = "-f",
      paramLabel = "IMAGE",
      description =
          "Train on this image (PPM, PNG, JPEG...); default: desk-scene, the tutorial image.")
  Path image;

  @Option(names = "-d", paramLabel = "DEVICE", description = "Start with live video from a camera.")
  String device;

  @Option(
      names = "--sim-camera",
      description =
          "Start with live video from the simulator's camera: a simulated robot in the hall"
              + " looking at colored things.")
  boolean simCamera;

  @Option(
      names = "--sim-port",
      paramLabel = "PORT",
      description = "TCP port of that simulated robot (default 8101; 0 = any; -1 = none).")
  Integer simPort;

  @Option(
      names = "-p",
      paramLabel = "PORT",
      description = "ACTS server port (default 5001; 0 = any).")
  Integer port;

  @Option(names = "--no-server", description = "Do not run the ACTS server.")
  boolean noServer;

  @Option(names = "-W", paramLabel = "WIDTH", description = "Image width (default 160).")
  Integer width;

  @Option(names = "-H", paramLabel = "HEIGHT", description = "Image height (default 120).")
  Integer height;

  @Option(names = "-w", paramLabel = "PIXELS", description = "Minimum blob width (default 5).")
  Integer minBlob;

  @Option(names = "-R", paramLabel = "FPS", description = "Server frame rate limit (default 30).")
  Integer fps;

  @Option(names = "-h", usageHelp = true, description = "Print this help and exit.")
  boolean help;

  @Option(
      names = "--view",
      paramLabel = "MODE",
      description = "Start in this view: overlay, thresh, raw or visible.")
  String view;

  @Option(names = "--channel", paramLabel = "N", description = "Start on channel N (1-32).")
  Integer channel;

  @Option(
      names = "--train",
      paramLabel = "X0,Y0,X1,Y1",
      description = "Add this rectangle (image pixels) to the channel at start; repeatable.")
  List<String> train = new ArrayList<>();

  @Option(names = "--magnification", paramLabel = "1-6", description = "Image magnification.")
  Integer magnification;

  @Option(names = "--blob-stats", description = "Print the blob stats once the image is shown.")
  boolean blobStats;

  @Override
  public String appName() {
    return "eztrain";
  }

  /**
   * The options as given (configuration size first, then -W/-H).
   *
   * @throws CommandLine.ParameterException if a value is out of range
   */
  public EzTrainOptions options() {
    EzTrainOptions d = EzTrainOptions.defaults();
    int w = width != null ? width : d.width();
    int h = height != null ? height : d.height();
    if (config != null && width == null && height == null) {
      try {
        ActsConfig cfg = ActsConfig.read(config);
        w = cfg.width();
        h = cfg.height();
      } catch (IOException e) {
        // The window reports the unreadable configuration with a dialog.
      }
    }
    try {
      List<int[]> rects = new ArrayList<>();
      for (String t : train) {
        rects.add(parseRect(t));
      }
      int c = channel != null ? channel : 1;
      ChannelBank.checkChannel(c);
      int m = magnification != null ? magnification : d.magnification();
      if (m < 1 || m > 6) {
        throw new IllegalArgumentException("--magnification must be 1..6, got " + m);
      }
      if (w < 1 || h < 1 || w > 4095 || h > 4095) {
        throw new IllegalArgumentException("-W and -H must be 1..4095 pixels, got " + w + "x" + h);
      }
      int sp = simPort != null ? simPort : d.simPort();
      if (sp < -1 || sp > 65535) {
        throw new IllegalArgumentException("--sim-port must be -1..65535, got " + sp);
      }
      int mb = minBlob != null ? minBlob : d.minBlobSize();
      if (mb < 1 || mb > 4095) {
        throw new IllegalArgumentException("-w must be 1..4095 pixels, got " + mb);
      }
      return new EzTrainOptions(
          config,
          image == null || TestScene.isBundledName(image) ? null : image,
          device,
          noServer ? -1 : (port != null ? port : d.port()),
          w,
          h,
          mb,
          fps != null ? fps : d.maxFps(),
          view != null ? ViewMode.parse(view) : d.view(),
          c,
          rects,
          m,
          Path.of(""),
          blobStats,
          simCamera,
          sp);
    } catch (IllegalArgumentException e) {
      throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage(), e);
    }
  }

  static int[] parseRect(String s) {
    String[] p = s.split(",", -1);
    if (p.length != 4) {
      throw new IllegalArgumentException("--train expects X0,Y0,X1,Y1, got '" + s + "'");
    }
    int[] r = new int[4];
    try {
      for (int i = 0; i < 4; i++) {
        r[i] = Integer.parseInt(p[i].trim());
      }
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException("--train expects four whole numbers, got '" + s + "'", e);
    }
    return r;
  }

  @Override
  public DesktopApp open(Stage stage, AppEnvironment env) {
    EzTrainWindow w = new EzTrainWindow(stage, env, options());
    w.show();
    return w;
  }

  @Override
  public Integer call() {
    try {
      options();
    } catch (CommandLine.ParameterException e) {
      spec.commandLine().getErr().println("eztrain: " + e.getMessage());
      return 2;
    }
    return AppLauncher.runUntilClosed(this, spec.commandLine().getErr());
  }
}
