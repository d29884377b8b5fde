package org.jaria.net.sav;

import java.io.IOException;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import org.jaria.net.data.VideoFrame;
import org.jaria.net.provider.VideoSource;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.info.ArServerHandlerVideo;

/**
 * ACTS's SAV server: the frames ACTS tracks, served as JPEG over ArNetworking (by default on port
 * 7070), where ARIA's {@code ArHybridForwarderVideo} (serverDemo, ARNL's guiServer) and {@code
 * getVideoExample} fetch them with {@code sendVideo} and {@code videoSize}. {@code jaria acts -S}
 * does not start it, as in ACTS.
 *
 * <pre>{@code
 * try (SavServer sav = SavServer.open(pipeline::lastFrame, acts::framesProcessed, 160, 120,
 *     "127.0.0.1", SavServer.DEFAULT_PORT)) { ... }
 * }</pre>
 */
public final class SavServer implements AutoCloseable {

  /** ACTS's SAV port. */
  public static final int DEFAULT_PORT = 7070;

  private final ArServerBase server;

  private SavServer(ArServerBase server) {
    this.server = server;
  }

  /**
   * Starts serving.
   *
   * @param pixels the newest frame's pixels, 0xRRGGBB, row by row (a copy)
   * @param frameNumber counts the frames, so an unchanged frame is not converted again
   * @param bind address to listen on (null: this computer only)
   * @throws IOException if the port cannot be opened
   */
  public static SavServer open(
      Supplier<int[]> pixels,
      LongSupplier frameNumber,
      int width,
      int height,
      String bind,
      int port)
      throws IOException {
    ArServerBase s =
        new ArServerBase(
            ServerOptions.builder()
                .serverName("ACTS SAV")
                .port(port)
                .bindAddress(bind == null ? "127.0.0.1" : bind)
                .build());
    new ArServerHandlerVideo(s, new Frames(pixels, frameNumber, width, height));
    s.open();
    return new SavServer(s);
  }

  /** The port it listens on. */
  public int getPort() {
    return server.getPort();
  }

  /** The ArNetworking server, for counters. */
  public ArServerBase getServer() {
    return server;
  }

  @Override
  public void close() {
    server.close();
  }

  /** ACTS's frames as a video source: converted to RGB bytes once per new frame. */
  static final class Frames implements VideoSource {
    private final Supplier<int[]> pixels;
    private final LongSupplier frameNumber;
    private final int width;
    private final int height;
    private VideoFrame last;
    private long lastNumber = -1;

    Frames(Supplier<int[]> pixels, LongSupplier frameNumber, int width, int height) {
      this.pixels = pixels;
      this.frameNumber = frameNumber;
      this.width = width;
      this.height = height;
    }

    @Override
    public String getName() {
      return "ACTS camera";
    }

    @Override
    public synchronized VideoFrame getLatestFrame() {
      long n = frameNumber.getAsLong();
      if (n <= 0) {
        return null;
      }
      if (n != lastNumber) {
        last = new VideoFrame(n, VideoFrame.Format.RGB, width, height, rgb(pixels.get()));
        lastNumber = n;
      }
      return last;
    }

    /** 0xRRGGBB ints as R, G, B bytes. */
    static byte[] rgb(int[] px) {
      byte[] b = new byte[px.length * 3];
      for (int i = 0, j = 0; i < px.length; i++) {
        b[j++] = (byte) (px[i] >> 16);
        b[j++] = (byte) (px[i] >> 8);
        b[j++] = (byte) px[i];
      }
      return b;
    }
  }
}
