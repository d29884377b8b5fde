package org.jaria.apps.eztrain;

import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.server.ActsServer;
import org.jaria.acts.server.ServerSettings;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.clock.Clock;

/**
 * The ACTS server that runs while EZ-Train is open (as ACTS itself does): it tracks the frame being
 * trained on with the channels being trained, so a robot program connected to it sees the training
 * as it happens.
 */
final class ActsServerControl implements AutoCloseable {

  private final EzTrainSession session;
  private final TrackerSettings settings;
  private final int port;
  private final int maxFps;
  private volatile ActsServer server;
  private long startNanos;
  private String failure;

  /**
   * @param port TCP port (0: any free port; -1: no server)
   */
  ActsServerControl(EzTrainSession session, TrackerSettings settings, int port, int maxFps) {
    this.session = session;
    this.settings = settings;
    this.port = port;
    this.maxFps = maxFps;
  }

  /** Starts the server (if wanted); problems are reported to {@code out}, never thrown. */
  void start(Consumer<String> out) {
    if (port < 0) {
      out.accept("ACTS server off (--no-server, or a screenshot)");
      return;
    }
    VisionPipeline pipeline =
        new VisionPipeline(new FrameSource(session), session.bank(), settings);
    ActsServer s =
        new ActsServer(
            pipeline,
            ServerSettings.DEFAULT
                .withAddress(ServerSettings.DEFAULT.bindHost(), port)
                .withMaxFps(maxFps),
            Clock.system());
    try {
      s.start();
      server = s;
      startNanos = System.nanoTime();
      out.accept(
          "ACTS server listening on port "
              + s.getPort()
              + ": robot programs (ArACTS_1_2) see the channels as they are trained");
    } catch (IOException e) {
      failure = e.getMessage();
      out.accept("ACTS server not started: " + e.getMessage());
    }
  }

  /** The port the server listens on, or -1. */
  int port() {
    return server == null ? -1 : server.getPort();
  }

  /**
   * Waits until the server has tracked two more frames, so its replies reflect every channel change
   * made before this call.
   *
   * @return false if there is no server or that took longer than {@code timeoutMs}
   */
  boolean awaitFreshFrames(long timeoutMs) throws InterruptedException {
    ActsServer s = server;
    return s != null && s.awaitFrames(s.framesProcessed() + 2, timeoutMs, TimeUnit.MILLISECONDS);
  }

  /** The port asked for (for saved configurations). */
  int configuredPort() {
    return port < 0 ? 5001 : (port == 0 ? port() : port);
  }

  /** For the status bar. */
  String describe() {
    if (server != null) {
      return "ACTS server: port " + server.getPort();
    }
    return failure != null ? "ACTS server: not running" : "ACTS server: off";
  }

  /** The server's frame rate, for Info → Timing. */
  String timing() {
    if (server == null) {
      return "no ACTS server";
    }
    double s = (System.nanoTime() - startNanos) / 1e9;
    return String.format(
        Locale.ROOT,
        "ACTS server %.1f frames/s (%d frames, %d requests)",
        s > 0 ? server.framesProcessed() / s : 0,
        server.framesProcessed(),
        server.requestsServed());
  }

  @Override
  public void close() {
    if (server != null) {
      server.close();
      server = null;
    }
  }

  /** The session's current frame as an image source for the server's pipeline. */
  static final class FrameSource implements ImageSource {
    private final EzTrainSession session;

    FrameSource(EzTrainSession session) {
      this.session = session;
    }

    @Override
    public int width() {
      return session.width();
    }

    @Override
    public int height() {
      return session.height();
    }

    @Override
    public boolean nextFrame(int[] rgb) {
      int[] px = session.frame().pixels();
      System.arraycopy(px, 0, rgb, 0, px.length);
      return true;
    }

    @Override
    public String describe() {
      return "EZ-Train's frame " + width() + "x" + height();
    }
  }
}
