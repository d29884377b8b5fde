package org.jaria.acts.image;

import java.io.IOException;

/**
 * Loads OpenCV's native library once per process (through {@code nu.pattern.OpenCV.loadLocally()},
 * which unpacks the library for this operating system from the openpnp jar). Thread-safe.
 */
public final class OpenCvLoader {

  private static final Object LOCK = new Object();
  private static boolean loaded;
  private static String failure;

  private OpenCvLoader() {}

  /**
   * Makes sure OpenCV is loaded.
   *
   * @throws IOException if the native library cannot be loaded on this machine (the message says
   *     why); every later call fails the same way without retrying
   */
  public static void load() throws IOException {
    synchronized (LOCK) {
      if (loaded) {
        return;
      }
      if (failure == null) {
        try {
          nu.pattern.OpenCV.loadLocally();
          loaded = true;
          return;
        } catch (RuntimeException | LinkageError e) {
          failure =
              "OpenCV's native library could not be loaded on this machine ("
                  + e
                  + "); cameras need it, still images (-f) do not";
        }
      }
      throw new IOException(failure);
    }
  }
}
