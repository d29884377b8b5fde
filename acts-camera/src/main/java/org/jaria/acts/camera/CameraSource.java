package org.jaria.acts.camera;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.jaria.acts.image.LiveCamera;
import org.jaria.acts.image.RgbImage;
import org.opencv.core.Mat;
import org.opencv.core.Size;
import org.opencv.imgproc.Imgproc;
import org.opencv.videoio.VideoCapture;
import org.opencv.videoio.Videoio;

/**
 * A live camera (or a video file) read through OpenCV's {@code VideoCapture}, scaled to the working
 * size. ACTS's {@code -d} device: a number picks a camera by index ({@code -1} means the first one,
 * as in ACTS), anything else is a device path such as {@code /dev/video0} or a video file.
 *
 * <p>{@link #nextFrame(int[])} blocks until the camera delivers the next frame; {@link #close()}
 * may be called from another thread and waits for a read in progress to end.
 */
public final class CameraSource implements LiveCamera {

  /** Camera parameters settable with {@code -s name value} (ACTS's {@code -P} lists them). */
  public static final Map<String, Integer> PARAMETERS;

  static {
    Map<String, Integer> m = new LinkedHashMap<>();
    m.put("brightness", Videoio.CAP_PROP_BRIGHTNESS);
    m.put("contrast", Videoio.CAP_PROP_CONTRAST);
    m.put("saturation", Videoio.CAP_PROP_SATURATION);
    m.put("hue", Videoio.CAP_PROP_HUE);
    m.put("gain", Videoio.CAP_PROP_GAIN);
    m.put("exposure", Videoio.CAP_PROP_EXPOSURE);
    m.put("auto_exposure", Videoio.CAP_PROP_AUTO_EXPOSURE);
    m.put("gamma", Videoio.CAP_PROP_GAMMA);
    m.put("sharpness", Videoio.CAP_PROP_SHARPNESS);
    m.put("backlight", Videoio.CAP_PROP_BACKLIGHT);
    m.put("auto_wb", Videoio.CAP_PROP_AUTO_WB);
    m.put("wb_temperature", Videoio.CAP_PROP_WB_TEMPERATURE);
    m.put("focus", Videoio.CAP_PROP_FOCUS);
    m.put("autofocus", Videoio.CAP_PROP_AUTOFOCUS);
    m.put("zoom", Videoio.CAP_PROP_ZOOM);
    m.put("fps", Videoio.CAP_PROP_FPS);
    m.put("frame_width", Videoio.CAP_PROP_FRAME_WIDTH);
    m.put("frame_height", Videoio.CAP_PROP_FRAME_HEIGHT);
    PARAMETERS = Collections.unmodifiableMap(m);
  }

  private final VideoCapture capture;
  private final String device;
  private final int width;
  private final int height;
  private final Mat frame = new Mat();
  private final Mat scaled = new Mat();
  private final Mat converted = new Mat();
  private byte[] bgr;
  private boolean closed;

  private CameraSource(VideoCapture capture, String device, int width, int height) {
    this.capture = capture;
    this.device = device;
    this.width = width;
    this.height = height;
  }

  /**
   * Opens a camera or video.
   *
   * @param device a camera index ({@code -1} = the first camera) or a device/video file path
   * @throws IOException if there is no such camera or file, or OpenCV cannot open it; the message
   *     says what to try instead
   */
  public static CameraSource open(String device, int width, int height) throws IOException {
    RgbImage.checkSize(width, height);
    Integer index = parseIndex(device);
    if (index == null && !pathExists(device)) {
      throw new IOException(
          "no camera or video file at '"
              + device
              + "': give a camera number (-d 0) or an existing device path or video file, or use"
              + " a still image with -f FILE");
    }
    OpenCvLoader.load();
    VideoCapture cap = index != null ? new VideoCapture(index) : new VideoCapture(device);
    if (!cap.isOpened()) {
      cap.release();
      throw new IOException(
          index != null
              ? "no camera found at device index "
                  + index
                  + " (OpenCV could not open it): connect a camera, pick another with -d N, or"
                  + " use a still image with -f FILE"
              : "OpenCV could not open '"
                  + device
                  + "' as a camera or video: check the path and permissions, or use a still"
                  + " image with -f FILE");
    }
    return new CameraSource(cap, device, width, height);
  }

  private static boolean pathExists(String device) {
    try {
      return Files.exists(Path.of(device));
    } catch (InvalidPathException e) {
      return false;
    }
  }

  private static Integer parseIndex(String device) {
    try {
      int i = Integer.parseInt(device.strip());
      return Math.max(0, i);
    } catch (NumberFormatException e) {
      return null;
    }
  }

  /** The parameter names and what they set, one per line (ACTS's {@code -P}). */
  public static String parameterList() {
    StringBuilder b = new StringBuilder("Camera parameters for -s NAME VALUE (OpenCV properties;");
    b.append(" what a camera accepts and the value ranges depend on its driver):\n");
    for (String name : PARAMETERS.keySet()) {
      b.append("  ").append(name).append('\n');
    }
    return b.toString();
  }

  /**
   * Sets a camera parameter (see {@link #PARAMETERS}).
   *
   * @return whether the camera accepted it
   * @throws IllegalArgumentException if the name is unknown
   */
  @Override
  public synchronized boolean setParameter(String name, double value) {
    Integer prop = PARAMETERS.get(name.toLowerCase(Locale.ROOT));
    if (prop == null) {
      throw new IllegalArgumentException(
          "unknown camera parameter '" + name + "'; -P lists the names");
    }
    return !closed && capture.set(prop, value);
  }

  @Override
  public int width() {
    return width;
  }

  @Override
  public int height() {
    return height;
  }

  @Override
  public synchronized boolean nextFrame(int[] rgb) throws IOException {
    if (closed) {
      throw new IOException("camera " + device + " is closed");
    }
    if (!capture.read(frame) || frame.empty()) {
      throw new IOException(
          "camera " + device + " stopped delivering frames (unplugged, or the video ended)");
    }
    Mat src = frame;
    if (src.channels() != 3) {
      Imgproc.cvtColor(
          src, converted, src.channels() == 4 ? Imgproc.COLOR_BGRA2BGR : Imgproc.COLOR_GRAY2BGR);
      src = converted;
    }
    if (src.cols() != width || src.rows() != height) {
      Imgproc.resize(src, scaled, new Size(width, height), 0, 0, Imgproc.INTER_AREA);
      src = scaled;
    }
    int n = width * height;
    if (bgr == null || bgr.length != 3 * n) {
      bgr = new byte[3 * n];
    }
    src.get(0, 0, bgr);
    for (int i = 0, j = 0; i < n; i++, j += 3) {
      rgb[i] = ((bgr[j + 2] & 0xFF) << 16) | ((bgr[j + 1] & 0xFF) << 8) | (bgr[j] & 0xFF);
    }
    return true;
  }

  @Override
  public String describe() {
    return "camera " + device + " " + width + "x" + height;
  }

  @Override
  public synchronized void close() {
    if (!closed) {
      closed = true;
      capture.release();
      frame.release();
      scaled.release();
      converted.release();
    }
  }
}
