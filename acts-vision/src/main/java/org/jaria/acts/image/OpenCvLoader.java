package org.jaria.acts.image;

import java.io.IOException;

/**
 * Loads OpenCV's native library once per process (through {@code nu.pattern.OpenCV.loadLocally()},
 * which unpacks the library for this operating system from the openpnp jar). Thread-safe: the JVM
 * initialises the holder class once, so the library is loaded (or fails) exactly once, on first
 * use.
 *
 * <p>OpenCV is an optional dependency of this library: a program that only speaks the ACTS protocol
 * (the {@code ArACTS_1_2} client, the server on still images or the simulator's camera) does not
 * need its 110 MB jar. Only a live camera ({@link CameraSource}) does; without the jar on the class
 * path {@link #load()} says which library to add.
 */
public final class OpenCvLoader {

  private OpenCvLoader() {}

  /** Holds the outcome of the one load attempt: null if it worked, else why not. */
  private static final class Outcome {
    static final String FAILURE = tryLoad();

    private static String tryLoad() {
      if (OpenCvLoader.class.getClassLoader().getResource("nu/pattern/OpenCV.class") == null) {
        return "OpenCV is not on the class path: a live camera needs the library"
            + " org.openpnp:opencv (acts-vision declares it optional; add it to your project's"
            + " dependencies); still images (-f) do not";
      }
      try {
        nu.pattern.OpenCV.loadLocally();
        return null;
      } catch (RuntimeException | LinkageError e) {
        return "OpenCV's native library could not be loaded on this machine ("
            + e
            + "); cameras need it, still images (-f) do not";
      }
    }
  }

  /**
   * Makes sure OpenCV is loaded.
   *
   * @throws IOException if the native library cannot be loaded on this machine (the message says
   *     why); every later call fails the same way without retrying
   */
  public static void load() throws IOException {
    if (Outcome.FAILURE != null) {
      throw new IOException(Outcome.FAILURE);
    }
  }
}
