package org.jaria.acts.image;

import java.io.IOException;
import java.util.Optional;
import java.util.ServiceLoader;

/** Live cameras through the {@link CameraDriver} on the class path (module {@code acts-camera}). */
public final class Cameras {

  /** What to say when a camera is asked for and no driver is on the class path. */
  static final String NO_DRIVER =
      "live cameras need JAria's camera driver (the module org.jaria:acts-camera, which brings"
          + " OpenCV): ./jaria fetches it the first time a command asks for a camera; a program"
          + " of your own adds it to its dependencies. Still images (-f FILE) need nothing more";

  private Cameras() {}

  /** The camera driver on the class path, if there is one. */
  public static Optional<CameraDriver> driver() {
    return ServiceLoader.load(CameraDriver.class).findFirst();
  }

  /**
   * Opens a camera or video file through the driver on the class path.
   *
   * @param device a camera index ({@code -1} = the first camera) or a device or video file path
   * @throws IOException if there is no driver, no such camera or file, or it cannot be opened (the
   *     message says what to do)
   */
  public static LiveCamera open(String device, int width, int height) throws IOException {
    return driver().orElseThrow(() -> new IOException(NO_DRIVER)).open(device, width, height);
  }

  /**
   * The parameters a camera takes (ACTS's {@code -P}).
   *
   * @throws IOException if there is no driver on the class path (the message says how to get one)
   */
  public static String parameterList() throws IOException {
    return driver().orElseThrow(() -> new IOException(NO_DRIVER)).parameterList();
  }
}
