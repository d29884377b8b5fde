package org.jaria.apps.eztrain;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ChannelLutFile;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.PlaneLimits;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.config.ActsConfig;
import org.jaria.acts.image.RgbImage;

/**
 * EZ-Train's model: the 32 channels being trained, the current frame at the working size, and the
 * training operations on the selected channel. No JavaFX here.
 *
 * <p>Threads: the {@link ChannelBank} and the current frame may be read from any thread (the ACTS
 * server and the view read them while training goes on). The training operations use a {@link
 * Trainer}, which must be driven from one thread: call them all from the same worker thread.
 */
public final class EzTrainSession {

  private final ChannelBank bank;
  private final Trainer trainer;
  private final int width;
  private final int height;
  private final Path baseDir;
  private final AtomicInteger unsaved = new AtomicInteger();
  private volatile RgbImage frame;
  private volatile int channel = 1;

  /**
   * A session.
   *
   * @param bank the channels (shared with the ACTS server)
   * @param width working image width (every frame is scaled to it)
   * @param height working image height
   * @param baseDir folder relative channel file names are resolved against
   */
  public EzTrainSession(ChannelBank bank, int width, int height, Path baseDir) {
    this.bank = bank;
    this.trainer = new Trainer(bank);
    this.width = width;
    this.height = height;
    this.baseDir = baseDir;
    this.frame = new RgbImage(width, height);
  }

  /** The channels. */
  public ChannelBank bank() {
    return bank;
  }

  /** Working image width. */
  public int width() {
    return width;
  }

  /** Working image height. */
  public int height() {
    return height;
  }

  /** The folder relative channel file names are resolved against. */
  public Path baseDir() {
    return baseDir;
  }

  /** The current frame (any thread). */
  public RgbImage frame() {
    return frame;
  }

  /** Replaces the current frame, scaling it to the working size (any thread). */
  public void setFrame(RgbImage image) {
    frame =
        image.width() == width && image.height() == height
            ? image.copy()
            : image.scaled(width, height);
  }

  /** The selected channel 1..32 (any thread). */
  public int channel() {
    return channel;
  }

  /** Channels changed since they were last loaded or saved (bit c-1 = channel c; any thread). */
  public int unsavedMask() {
    return unsaved.get();
  }

  private void touched() {
    int bit = 1 << (channel - 1);
    unsaved.getAndUpdate(m -> m | bit);
  }

  private void saved(int c) {
    int bit = 1 << (c - 1);
    unsaved.getAndUpdate(m -> m & ~bit);
  }

  // ---------------------------------------------------------------- worker thread

  /** Selects the channel the tools act on. */
  public void selectChannel(int c) {
    trainer.setChannel(ChannelBank.checkChannel(c));
    channel = c;
  }

  /** Sets the Draw/Erase brush size (1..9). */
  public void setBrushSize(int size) {
    trainer.setBrushSize(size);
  }

  /**
   * Add or Remove: the colours of the frame's rectangle (x0, y0)-(x1, y1), pixels inclusive, with
   * their neighbourhoods. Each distinct colour is trained once, so a large uniform rectangle costs
   * little.
   */
  public void trainRect(boolean add, int x0, int y0, int x1, int y1) {
    RgbImage f = frame;
    int left = Math.max(0, Math.min(x0, x1));
    int right = Math.min(f.width() - 1, Math.max(x0, x1));
    int top = Math.max(0, Math.min(y0, y1));
    int bottom = Math.min(f.height() - 1, Math.max(y0, y1));
    if (left > right || top > bottom) {
      return;
    }
    RgbImage colors = distinctColors(f, left, top, right, bottom);
    if (add) {
      trainer.addRect(colors, 0, 0, colors.width() - 1, 0);
    } else {
      trainer.removeRect(colors, 0, 0, colors.width() - 1, 0);
    }
    touched();
  }

  /** The distinct colours of a rectangle of {@code f}, as a one-row image. */
  static RgbImage distinctColors(RgbImage f, int left, int top, int right, int bottom) {
    int[] px = f.pixels();
    int n = 0;
    int[] all = new int[(right - left + 1) * (bottom - top + 1)];
    for (int y = top; y <= bottom; y++) {
      for (int x = left; x <= right; x++) {
        all[n++] = px[y * f.width() + x] & 0xFFFFFF;
      }
    }
    Arrays.sort(all);
    int k = 0;
    for (int i = 0; i < n; i++) {
      if (k == 0 || all[i] != all[k - 1]) {
        all[k++] = all[i];
      }
    }
    return new RgbImage(k, 1, Arrays.copyOf(all, k));
  }

  /**
   * Draw or Erase along a mouse stroke: the brush at every point, undone as one step.
   *
   * @param points image coordinates {x, y} of the stroke
   */
  public void stroke(boolean draw, List<int[]> points) {
    if (points.isEmpty()) {
      return;
    }
    RgbImage f = frame;
    trainer.beginGroup();
    try {
      for (int[] p : points) {
        if (draw) {
          trainer.draw(f, p[0], p[1]);
        } else {
          trainer.erase(f, p[0], p[1]);
        }
      }
    } finally {
      trainer.endGroup();
    }
    touched();
  }

  /**
   * Pick: the pixel's colour as EZ-Train prints it, e.g. "(12, 40): R 200 G 30 B 25". Changes
   * nothing, so any thread may call it.
   */
  public String pick(int x, int y) {
    RgbImage f = frame;
    if (!f.contains(x, y)) {
      return "(" + x + ", " + y + ") is outside the image";
    }
    return "(" + x + ", " + y + "): " + Trainer.describe(f.get(x, y));
  }

  /** Undo on the selected channel; false if there was nothing to undo. */
  public boolean undo() {
    boolean done = trainer.undo();
    if (done) {
      touched();
    }
    return done;
  }

  /** Clear Training on the selected channel. */
  public void clearTraining() {
    trainer.clearTraining();
    touched();
  }

  /** Sets one plane's limits (manual training). */
  public void setLimits(ColorPlane plane, PlaneLimits limits) {
    if (!trainer.getLimits(plane).equals(limits)) {
      trainer.setLimits(plane, limits);
      touched();
    }
  }

  /** Fill Plane. */
  public void fillPlane(ColorPlane plane) {
    trainer.fillPlane(plane);
    touched();
  }

  /** Clear Plane. */
  public void clearPlane(ColorPlane plane) {
    trainer.clearPlane(plane);
    touched();
  }

  /** Sets how many blobs the selected channel tracks (1..10). */
  public void setTrackedBlobs(int n) {
    bank.setTrackedBlobs(channel, n);
  }

  /** The file of a channel file name: as is if absolute, else in the base folder. */
  public Path resolve(String fileName) {
    return baseDir.resolve(fileName);
  }

  /**
   * Loads a channel LUT file into the selected channel (undoable) and takes its name.
   *
   * @throws IOException if the file cannot be read or is not a channel file (message names it)
   */
  public void loadChannel(Path file) throws IOException {
    Channel c = ChannelLutFile.read(file);
    trainer.load(c);
    bank.setFileName(channel, nameFor(file));
    saved(channel);
  }

  /** Saves the selected channel to {@code file} and takes its name. */
  public void saveChannel(Path file) throws IOException {
    ChannelLutFile.write(bank.copyOf(channel), file);
    bank.setFileName(channel, nameFor(file));
    saved(channel);
  }

  private String nameFor(Path file) {
    Path abs = file.toAbsolutePath().normalize();
    Path base = baseDir.toAbsolutePath().normalize();
    return abs.startsWith(base) ? base.relativize(abs).toString() : abs.toString();
  }

  /** Loads a runtime configuration: every listed channel file and its tracked-blob count. */
  public ActsConfig loadConfig(Path file) throws IOException {
    ActsConfig cfg = ActsConfig.read(file);
    Path dir = file.toAbsolutePath().getParent();
    cfg.applyTo(bank, dir);
    unsaved.set(0);
    return cfg;
  }

  /**
   * Saves a runtime configuration listing the trained channels (not the channel files themselves,
   * as in ACTS). Channel file names are written relative to the configuration's folder.
   */
  public ActsConfig saveConfig(Path file, int minBlobSize, int port) throws IOException {
    Path dir = file.toAbsolutePath().normalize().getParent();
    List<ActsConfig.ChannelEntry> entries = new ArrayList<>();
    for (int c = 1; c <= ChannelBank.NUM_CHANNELS; c++) {
      if (!bank.copyOf(c).isEmpty()) {
        Path lut = resolve(bank.getFileName(c)).toAbsolutePath().normalize();
        String name = lut.startsWith(dir) ? dir.relativize(lut).toString() : lut.toString();
        entries.add(new ActsConfig.ChannelEntry(c, name, bank.getTrackedBlobs(c)));
      }
    }
    ActsConfig cfg = new ActsConfig(width, height, minBlobSize, port, entries);
    cfg.write(file);
    return cfg;
  }
}
