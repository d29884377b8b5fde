package org.jaria.apps.eztrain;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jaria.acts.camera.CameraSource;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.RgbImage;
import org.jaria.apps.fx.AppPrefs;
import org.jaria.apps.fx.Prompts;

/**
 * EZ-Train's file work: still images, cameras and the simulator's camera, channel files and runtime
 * configurations. Everything that reads or writes runs on the window's worker thread and reports
 * failures in a dialog that says what to do.
 */
final class EzTrainFiles {

  private final EzTrainWindow w;
  private final EzTrainState state;
  private final EzTrainSession session;
  private final Prompts prompts;
  private final AppPrefs prefs;
  private final EzTrainOptions options;

  EzTrainFiles(
      EzTrainWindow w,
      EzTrainState state,
      EzTrainSession session,
      Prompts prompts,
      AppPrefs prefs,
      EzTrainOptions options) {
    this.w = w;
    this.state = state;
    this.session = session;
    this.prompts = prompts;
    this.prefs = prefs;
    this.options = options;
  }

  void loadImageDialog() {
    prompts
        .chooseOpenFile("Load image", EzTrainWindow.IMAGE_FILTER, lastDir())
        .ifPresent(this::loadImage);
  }

  /** Loads a still image to train on (stops live video). */
  public void loadImage(Path file) {
    w.submitIo(
        "Loading " + file.getFileName(),
        () -> ImageFiles.read(file),
        img -> {
          w.stopFeed();
          session.setFrame(img);
          prefs.put("lastDir", String.valueOf(file.toAbsolutePath().getParent()));
          w.print(
              "Image "
                  + file
                  + " ("
                  + img.width()
                  + "x"
                  + img.height()
                  + ") shown at "
                  + session.width()
                  + "x"
                  + session.height());
        },
        "EZ-Train reads PPM (P6/P3), PNG, JPEG, BMP and GIF images.");
  }

  void liveVideoDialog() {
    prompts
        .askText("Live video", "Camera number (0 = first) or device path", prefs.get("device", "0"))
        .ifPresent(this::startCamera);
  }

  /** Opens a camera (off the JavaFX thread) and trains on its video. */
  public void startCamera(String device) {
    prefs.put("device", device);
    w.submitIo(
        "Opening camera " + device,
        () -> firstFrame(CameraSource.open(device, session.width(), session.height())),
        w::useVideoSource,
        "Without a camera, train on a still image: File → Load Image.");
  }

  /** Trains on live video from the simulator's camera (see {@link SimulatorCamera}). */
  void simulatorCamera() {
    w.submitIo(
        "Opening the simulator's camera",
        () -> firstFrame(w.simCameraHook().open(session.width(), session.height())),
        w::useVideoSource,
        "Train on a still image (File → Load Image) or a real camera (File → Live Video)"
            + " instead.");
  }

  /**
   * Reads the source's first frame into the session (worker thread), so that work queued after
   * opening it — training from the command line, a screenshot — sees the video, not the picture
   * shown before.
   */
  private ImageSource firstFrame(ImageSource source) throws IOException {
    try {
      int[] px = new int[source.width() * source.height()];
      if (source.nextFrame(px)) {
        session.setFrame(new RgbImage(source.width(), source.height(), px));
      }
      return source;
    } catch (IOException | RuntimeException e) {
      source.close();
      throw e;
    }
  }

  void channelFileEntered() {
    Path p = session.resolve(state.fileName.get());
    int c = state.channel.get();
    if (Files.isRegularFile(p)) {
      loadChannel(p);
    } else {
      session.bank().setFileName(c, state.fileName.get());
      w.status("Channel " + c + " will be saved as " + p);
    }
  }

  void loadChannelByName() {
    loadChannel(session.resolve(state.fileName.get()));
  }

  void loadChannelDialog() {
    prompts
        .chooseOpenFile("Load channel", EzTrainWindow.LUT_FILTER, lastDir())
        .ifPresent(this::loadChannel);
  }

  /** Loads a channel file into the selected channel (undoable). */
  public void loadChannel(Path file) {
    int c = state.channel.get();
    w.submitIo(
        "Loading channel " + c,
        () -> {
          session.loadChannel(file);
          return session.bank().getFileName(c);
        },
        name -> {
          if (state.channel.get() == c) {
            state.fileName.set(name);
          }
          w.print("Channel " + c + " loaded from " + file);
        },
        "Channel files are written by EZ-Train's Save Channel. Check the name, or choose the file"
            + " with the … button.");
  }

  /** Saves the selected channel to the file named in the console. */
  public void saveChannel() {
    saveChannel(session.resolve(state.fileName.get()));
  }

  void saveChannelAsDialog() {
    prompts
        .chooseSaveFile(
            "Save channel as", EzTrainWindow.LUT_FILTER, lastDir(), state.fileName.get())
        .ifPresent(this::saveChannel);
  }

  /** Saves the selected channel to {@code file}. */
  public void saveChannel(Path file) {
    int c = state.channel.get();
    w.submitIo(
        "Saving channel " + c,
        () -> {
          session.saveChannel(file);
          return session.bank().getFileName(c);
        },
        name -> {
          if (state.channel.get() == c) {
            state.fileName.set(name);
          }
          w.print("Channel " + c + " saved to " + file);
        },
        "Check that the folder exists and is writable, or use Save Channel As.");
  }

  void loadConfigDialog() {
    prompts
        .chooseOpenFile("Load runtime config", EzTrainWindow.CONFIG_FILTER, lastDir())
        .ifPresent(this::loadConfig);
  }

  /** Loads a runtime configuration (its channel files and tracked-blob counts). */
  public void loadConfig(Path file) {
    w.submitIo(
        "Loading configuration",
        () -> session.loadConfig(file),
        cfg -> {
          int c = state.channel.get();
          state.trackedBlobs.set(session.bank().getTrackedBlobs(c));
          state.fileName.set(session.bank().getFileName(c));
          w.print("Configuration " + file + ": " + cfg.channels().size() + " channel(s)");
          if (cfg.width() != session.width() || cfg.height() != session.height()) {
            w.print(
                "Note: it is for "
                    + cfg.width()
                    + "x"
                    + cfg.height()
                    + " images; restart with -c to work at that size");
          }
        },
        "A runtime configuration lists 'Channel N file blobs' lines; every channel file it names"
            + " must exist next to it.");
  }

  void saveConfigDialog() {
    prompts
        .chooseSaveFile("Save runtime config", EzTrainWindow.CONFIG_FILTER, lastDir(), "actsconfig")
        .ifPresent(this::saveConfig);
  }

  /** Saves a runtime configuration (the channel files must be saved separately). */
  public void saveConfig(Path file) {
    int unsaved = session.unsavedMask();
    w.submitIo(
        "Saving configuration",
        () -> session.saveConfig(file, options.minBlobSize(), w.serverConfiguredPort()),
        cfg -> {
          w.print(
              "Runtime configuration saved to "
                  + file
                  + " ("
                  + cfg.channels().size()
                  + " channels)");
          if (unsaved != 0) {
            w.print(
                "Remember: the configuration does not contain the channels; channel(s) "
                    + channelList(unsaved)
                    + " have unsaved changes (File → Save Channel)");
          }
        },
        "Check that the folder exists and is writable.");
  }

  static String channelList(int mask) {
    StringBuilder b = new StringBuilder();
    for (int c = 1; c <= 32; c++) {
      if ((mask & (1 << (c - 1))) != 0) {
        b.append(b.length() == 0 ? "" : ", ").append(c);
      }
    }
    return b.toString();
  }

  Path lastDir() {
    String d = prefs.get("lastDir", null);
    return d == null ? session.baseDir() : Path.of(d);
  }
}
