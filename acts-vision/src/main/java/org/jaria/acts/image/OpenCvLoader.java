package org.jaria.acts.image;

import java.io.IOException;

/**
 * Loads OpenCV's native library once per process (through {@code nu.pattern.OpenCV.loadLocally()},
 * which unpacks the library for this operating system from the openpnp jar). Thread-safe: the JVM
 * initialises the holder class once, so the library is loaded (or fails) exactly once, on first
 * use.
 */
public final class OpenCvLoader {

  private OpenCvLoader() {}

  /** Holds the outcome of the one load attempt: null if it worked, else why not. */
  private static final class Outcome {
    static final String FAILURE = tryLoad();

    private static String tryLoad() {
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
