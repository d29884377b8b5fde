package org.jaria.tools.acts;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.config.ActsConfig;
import org.jaria.acts.config.ActsPreferences;
import org.jaria.acts.image.Cameras;
import org.jaria.acts.image.ImageSequenceSource;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.LiveCamera;
import org.jaria.acts.image.StillImageSource;
import org.jaria.acts.server.ActsServer;
import org.jaria.acts.server.ServerSettings;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.clock.Clock;
import org.jaria.net.sav.SavServer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria acts}: the ACTS colour-tracking server, headless, with ACTS's command-line options
 * (thesis tables 5.59 and 5.61). It loads a runtime configuration of trained channels, reads frames
 * from a still image, a folder of images or a camera, and serves blob data to ARIA-style clients on
 * TCP port 5001 until a client asks it to quit ({@code --allow-quit}) or it is interrupted.
 *
 * <p>Settings come from, in increasing priority: the defaults, the preferences file ({@code --prefs
 * FILE}, or {@code ACTS.pref} in the current folder if present), the runtime configuration, and the
 * command line.
 */
@Command(
    name = "acts",
    sortOptions = false,
    description = {
      "ACTS color-tracking server (headless): tracks trained color channels in a still image,"
          + " a folder of images or a camera and serves the blobs on TCP (ArACTS_1_2 protocol)."
    },
    footer = {
      "",
      "Frame grabber drivers: JAria reads cameras through OpenCV (V4L2, DirectShow/MSMF,"
          + " AVFoundation as available); -G, -x, -n and -V are accepted for compatibility and"
          + " ignored.",
      "Example: jaria acts -c actsconfig -f desk-scene -p 5001"
    })
public final class ActsCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(names = "-c", paramLabel = "CONFIG", description = "Load this runtime configuration.")
  Path config;

  @Option(
      names = "-d",
      paramLabel = "DEVICE",
      description = "Camera: index (-1 = first) or device path / video file.")
  String device;

  @Option(
      names = "-f",
      paramLabel = "IMAGE",
      description =
          "Use this image file (PPM, PNG, JPEG...) or folder of images instead of a camera;"
              + " desk-scene is the shipped tutorial image.")
  Path imageFile;

  @Option(names = "-G", paramLabel = "DRIVER", description = "Grabber driver (ignored: OpenCV).")
  String driver;

  @Option(names = "-h", usageHelp = true, description = "Print this help and exit.")
  boolean help;

  @Option(names = "-H", paramLabel = "HEIGHT", description = "Image height in rows (default 120).")
  Integer height;

  @Option(names = "-i", description = "Inverted camera: rotate frames by 180 degrees.")
  boolean invert;

  @Option(names = "-n", paramLabel = "CHANNEL", description = "Grabber input channel (ignored).")
  Integer grabberChannel;

  @Option(names = "-p", paramLabel = "PORT", description = "TCP port (default 5001; 0 = any).")
  Integer port;

  @Option(names = "-P", description = "List the camera parameters for -s and exit.")
  boolean listParameters;

  @Option(names = "-R", paramLabel = "FPS", description = "Most frames per second (default 30).")
  Integer maxFps;

  @Option(
      names = "-s",
      arity = "2",
      paramLabel = "PARAM VALUE",
      hideParamSyntax = true,
      description = "Set a camera parameter, e.g. -s brightness 0.3 (repeatable; see -P).")
  List<String> cameraSettings = new ArrayList<>();

  @Option(
      names = "-S",
      description =
          "Do not start the SAV video server (ArNetworking on port 7070, or any free port with -p"
              + " 0).")
  boolean noAvServer;

  @Option(
      names = "--sav-port",
      paramLabel = "PORT",
      description = "Port of the SAV video server (default 7070; any free one with -p 0).")
  Integer savPort;

  @Option(
      names = "-t",
      arity = "0..1",
      fallbackValue = "",
      paramLabel = "CONFIG",
      description =
          "Run without graphics (always the case), loading CONFIG if given, as ACTS's -t does.")
  String headlessConfig;

  @Option(names = "-V", paramLabel = "PAL|NTSC", description = "Video standard (ignored).")
  String videoStandard;

  @Option(
      names = "-w",
      paramLabel = "PIXELS",
      description = "Minimum blob width and height in pixels (default 5).")
  Integer minBlobWidth;

  @Option(names = "-W", paramLabel = "WIDTH", description = "Image width in columns (default 160).")
  Integer width;

  @Option(names = "-x", description = "PXC200 grabber (not supported; ignored).")
  boolean pxc;

  @Option(names = "--prefs", paramLabel = "FILE", description = "Preferences file (ACTS.pref).")
  Path prefsFile;

  @Option(
      names = "--bind",
      paramLabel = "ADDRESS",
      description =
          "Listen on this address (default 127.0.0.1: this computer only, as the guiServer"
              + " without a login; 0.0.0.0: every interface, as ACTS).")
  String bindHost = ServerSettings.DEFAULT.bindHost();

  @Option(
      names = "--allow-quit",
      description = "Let a client's quit request ('1') stop the server, as ACTS does.")
  boolean allowQuit;

  @Option(names = "--max-clients", paramLabel = "N", description = "Most clients (default 16).")
  int maxClients = 16;

  @Option(
      names = "--merge",
      paramLabel = "GAP:DENSITY",
      description = "Merge nearby blobs of a channel, e.g. --merge 4:0.4.")
  String merge;

  private final CountDownLatch started = new CountDownLatch(1);
  private volatile ActsServer server;

  /** A command ready for picocli. */
  public ActsCommand() {}

  /** The running server (null before it started). */
  public ActsServer server() {
    return server;
  }

  /** Waits until the server listens (or the command failed before that). */
  public boolean awaitStarted(long timeout, TimeUnit unit) throws InterruptedException {
    return started.await(timeout, unit);
  }

  /** Asks a running command to stop and return. */
  public void requestStop() {
    ActsServer s = server;
    if (s != null) {
      s.requestStop();
    }
  }

  @Override
  public Integer call() throws Exception {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    try {
      return run(out, err);
    } finally {
      started.countDown();
      out.flush();
      err.flush();
    }
  }

  private int run(PrintWriter out, PrintWriter err) throws Exception {
    if (listParameters) {
      out.print(Cameras.parameterList());
      return 0;
    }
    notes(err);
    ActsPreferences prefs;
    try {
      prefs = loadPreferences(out);
    } catch (IOException e) {
      err.println("acts: " + e.getMessage());
      return 1;
    }
    Path cfgPath =
        headlessConfig != null && !headlessConfig.isEmpty() ? Path.of(headlessConfig) : config;
    if (cfgPath == null && !prefs.configFile().isEmpty()) {
      cfgPath = Path.of(prefs.configFile());
    }
    ActsConfig cfg =
        ActsConfig.DEFAULT
            .withSize(prefs.width(), prefs.height())
            .withMinBlobSize(prefs.minBlobSize())
            .withPort(prefs.port());
    ChannelBank bank = new ChannelBank();
    if (cfgPath != null) {
      try {
        cfg = ActsConfig.read(cfgPath);
        Path dir = cfgPath.toAbsolutePath().getParent();
        cfg.applyTo(bank, dir);
      } catch (IOException e) {
        err.println("acts: cannot load the configuration: " + e.getMessage());
        return 1;
      }
    }
    int w = width != null ? width : cfg.width();
    int h = height != null ? height : cfg.height();
    int p = port != null ? port : cfg.port();
    int minBlob = minBlobWidth != null ? minBlobWidth : cfg.minBlobSize();
    int fps = maxFps != null ? maxFps : prefs.framesPerSecond();
    TrackerSettings tracker;
    ServerSettings serverSettings;
    try {
      tracker = trackerSettings(minBlob);
      serverSettings = new ServerSettings(bindHost, p, fps, maxClients, allowQuit);
      cfg = new ActsConfig(w, h, minBlob, p, cfg.channels()); // checks the ranges
    } catch (IllegalArgumentException e) {
      err.println("acts: " + e.getMessage());
      return 2;
    }
    ImageSource source;
    try {
      source = openSource(prefs, w, h, err);
    } catch (IOException e) {
      err.println("acts: " + e.getMessage());
      return 1;
    }
    try {
      VisionPipeline pipeline = new VisionPipeline(source, bank, tracker);
      pipeline.setInverted(invert || prefs.invertedImage());
      ActsServer s = new ActsServer(pipeline, serverSettings, Clock.system());
      try {
        s.start();
      } catch (IOException e) {
        err.println("acts: " + e.getMessage());
        return 1;
      }
      server = s;
      Thread hook = new Thread(s::stop, "acts-" + s.getPort() + "-shutdown");
      Runtime.getRuntime().addShutdownHook(hook);
      out.println(
          "ACTS server listening on "
              + s.getAddress()
              + " (port "
              + s.getPort()
              + "); source: "
              + source.describe()
              + "; channels: "
              + describeChannels(bank)
              + "; min blob size "
              + minBlob
              + "; max "
              + (fps == 0 ? "unlimited" : fps)
              + " frames/s");
      SavServer sav = null;
      if (!noAvServer) {
        try {
          sav =
              SavServer.open(
                  pipeline::lastFrame,
                  s::framesProcessed,
                  w,
                  h,
                  bindHost == null || bindHost.isEmpty() ? null : bindHost,
                  savPort != null ? savPort : p == 0 ? 0 : SavServer.DEFAULT_PORT);
          out.println("SAV video server (ArNetworking) on port " + sav.getPort());
        } catch (IOException e) {
          err.println("acts: no SAV video server (" + e.getMessage() + "); -S turns it off");
        }
      }
      out.flush();
      started.countDown();
      try {
        s.awaitStopRequest();
      } finally {
        if (sav != null) {
          sav.close();
        }
        s.stop();
        try {
          Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException ignored) {
          // the JVM is already shutting down; the hook is running
        }
      }
      out.println("ACTS server stopped after " + s.framesProcessed() + " frames");
      return 0;
    } finally {
      source.close();
    }
  }

  private void notes(PrintWriter err) {
    if (driver != null) {
      err.println("acts: note: -G " + driver + " ignored; JAria reads cameras through OpenCV");
    }
    if (pxc) {
      err.println("acts: note: -x (PXC200 grabber) is not supported and is ignored");
    }
    if (grabberChannel != null) {
      err.println("acts: note: -n " + grabberChannel + " ignored (no multi-input grabber cards)");
    }
    if (videoStandard != null) {
      String v = videoStandard.toUpperCase(Locale.ROOT);
      if (!v.equals("PAL") && !v.equals("NTSC")) {
        err.println("acts: note: -V expects PAL or NTSC, got " + videoStandard + "; ignored");
      } else {
        err.println("acts: note: -V " + v + " ignored; OpenCV negotiates the video format");
      }
    }
    if (headlessConfig != null) {
      err.println("acts: note: -t: this server never shows graphics");
    }
  }

  private ActsPreferences loadPreferences(PrintWriter out) throws IOException {
    Path p = prefsFile;
    if (p == null && Files.isRegularFile(Path.of("ACTS.pref"))) {
      p = Path.of("ACTS.pref");
      out.println("Using preferences " + p.toAbsolutePath());
    }
    return p == null ? ActsPreferences.DEFAULT : ActsPreferences.read(p);
  }

  private TrackerSettings trackerSettings(int minBlob) {
    TrackerSettings t = TrackerSettings.DEFAULT.withMinBlobSize(minBlob);
    if (merge != null) {
      int colon = merge.indexOf(':');
      try {
        if (colon < 0) {
          throw new NumberFormatException();
        }
        t =
            t.withDensityMerge(
                Integer.parseInt(merge.substring(0, colon).strip()),
                Double.parseDouble(merge.substring(colon + 1).strip()));
      } catch (NumberFormatException e) {
        throw new IllegalArgumentException(
            "--merge expects GAP:DENSITY, e.g. 4:0.4, got '" + merge + "'", e);
      }
    }
    return t;
  }

  private ImageSource openSource(ActsPreferences prefs, int w, int h, PrintWriter err)
      throws IOException {
    Path image = imageFile;
    if (image == null && device == null && !prefs.imageFile().isEmpty()) {
      image = Path.of(prefs.imageFile());
    }
    if (image != null) {
      if (!cameraSettings.isEmpty()) {
        err.println("acts: note: -s camera parameters ignored for image files");
      }
      if (Files.isDirectory(image)) {
        return ImageSequenceSource.ofDirectory(image, w, h, true);
      }
      if (org.jaria.acts.image.TestScene.isBundledName(image)) {
        return new StillImageSource(
            org.jaria.acts.image.TestScene.load(),
            w,
            h,
            org.jaria.acts.image.TestScene.BUNDLED_NAME);
      }
      return StillImageSource.open(image, w, h);
    }
    String dev = device != null ? device : prefs.grabberDevice();
    LiveCamera cam = Cameras.open(dev, w, h);
    for (int i = 0; i + 1 < cameraSettings.size(); i += 2) {
      String name = cameraSettings.get(i);
      String value = cameraSettings.get(i + 1);
      try {
        if (!cam.setParameter(name, Double.parseDouble(value))) {
          err.println("acts: note: the camera did not accept -s " + name + " " + value);
        }
      } catch (NumberFormatException e) {
        cam.close();
        throw new IOException("-s " + name + " needs a number, got '" + value + "'", e);
      } catch (IllegalArgumentException e) {
        cam.close();
        throw new IOException(e.getMessage(), e);
      }
    }
    return cam;
  }

  private static String describeChannels(ChannelBank bank) {
    StringBuilder b = new StringBuilder();
    int active = bank.activeMask();
    for (int c = 1; c <= ChannelBank.NUM_CHANNELS; c++) {
      if ((active & (1 << (c - 1))) != 0) {
        if (b.length() > 0) {
          b.append(", ");
        }
        b.append(c).append(" (").append(bank.getTrackedBlobs(c)).append(" blobs)");
      }
    }
    return b.length() == 0 ? "none trained" : b.toString();
  }

  /** Runs the command (for use without the tools module). */
  public static void main(String[] args) {
    System.exit(new picocli.CommandLine(new ActsCommand()).execute(args));
  }
}
