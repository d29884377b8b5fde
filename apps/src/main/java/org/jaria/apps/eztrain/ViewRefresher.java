package org.jaria.apps.eztrain;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Supplier;
import javafx.application.Platform;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.blob.BlobTracker;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.image.RgbImage;

/**
 * Re-tracks the current frame and redraws the training image on its own thread ({@code
 * eztrain-view}) whenever something changed: a training step, a new video frame, another channel or
 * view mode. Requests that arrive while a refresh runs are merged into the next one, so live video
 * never queues up work; results are handed to the JavaFX thread.
 */
final class ViewRefresher implements AutoCloseable {

  /**
   * What to draw.
   *
   * @param channel the channel shown
   * @param mode the view mode
   * @param threshRgb the overlay colour
   * @param planes whether to draw the colour planes too
   */
  record Params(int channel, ViewMode mode, int threshRgb, boolean planes) {}

  private final EzTrainSession session;
  private final Supplier<Params> params;
  private final Consumer<Rendered> publish;
  private final BlobTracker tracker = new BlobTracker();
  private final BlobFrame blobs = new BlobFrame();
  private final Thread thread;
  private final Object lock = new Object();
  private List<CompletableFuture<Rendered>> waiting = new ArrayList<>();
  private boolean requested;
  private boolean stopped;
  private volatile TrackerSettings settings;

  ViewRefresher(
      EzTrainSession session,
      TrackerSettings settings,
      Supplier<Params> params,
      Consumer<Rendered> publish) {
    this.session = session;
    this.settings = settings;
    this.params = params;
    this.publish = publish;
    thread = new Thread(this::loop, "eztrain-view");
    thread.setDaemon(true);
    thread.start();
  }

  /** Changes the tracker settings (minimum blob size). */
  void setSettings(TrackerSettings s) {
    settings = s;
    request();
  }

  /** Asks for a refresh (any thread); many requests before it starts give one refresh. */
  void request() {
    synchronized (lock) {
      if (!stopped) {
        requested = true;
        lock.notifyAll();
      }
    }
  }

  /**
   * Asks for a refresh; the future completes (on the JavaFX thread, after the result was shown)
   * with a refresh that started after this call. Any thread.
   */
  CompletableFuture<Rendered> refresh() {
    CompletableFuture<Rendered> f = new CompletableFuture<>();
    synchronized (lock) {
      if (stopped) {
        f.cancel(false);
        return f;
      }
      waiting.add(f);
      requested = true;
      lock.notifyAll();
    }
    return f;
  }

  private void loop() {
    while (true) {
      List<CompletableFuture<Rendered>> mine;
      synchronized (lock) {
        while (!requested && !stopped) {
          try {
            lock.wait();
          } catch (InterruptedException e) {
            return;
          }
        }
        if (stopped) {
          return;
        }
        requested = false;
        mine = waiting;
        waiting = new ArrayList<>();
      }
      Rendered r;
      try {
        r = render(params.get());
      } catch (RuntimeException e) {
        mine.forEach(f -> f.completeExceptionally(e));
        continue;
      }
      Platform.runLater(
          () -> {
            publish.accept(r);
            mine.forEach(f -> f.complete(r));
          });
    }
  }

  private Rendered render(Params p) {
    RgbImage frame = session.frame();
    LookupTables tables = session.bank().tables();
    tracker.track(frame.pixels(), frame.width(), frame.height(), tables, settings, blobs);
    int[] view =
        TrainingRenderer.render(frame, tables, p.channel(), blobs, p.mode(), p.threshRgb());
    int[][] planes = null;
    int size = 0;
    if (p.planes()) {
      Channel c = session.bank().copyOf(p.channel());
      planes = new int[3][];
      for (ColorPlane plane : ColorPlane.all()) {
        planes[plane.ordinal()] = TrainingRenderer.renderPlane(c, plane);
      }
      size = c.cellsPerAxis();
    }
    return new Rendered(
        frame,
        view,
        p.channel(),
        p.mode(),
        blobs.blobs(p.channel()),
        blobs.processNanos(),
        planes,
        size);
  }

  @Override
  public void close() {
    synchronized (lock) {
      stopped = true;
      lock.notifyAll();
      waiting.forEach(f -> f.cancel(false));
      waiting.clear();
    }
    try {
      thread.join(5000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
