package org.jaria.apps.eztrain;

import java.io.IOException;
import org.jaria.acts.image.ImageSource;

/**
 * Where EZ-Train's File → Simulator Camera gets its frames: the hook for the simulator's camera
 * (what a simulated robot's camera sees). Any {@link ImageSource} will do; give one to {@link
 * EzTrainWindow#setSimCameraHook}, or hand a source directly to {@link
 * EzTrainWindow#useVideoSource}.
 *
 * <p>By default EZ-Train starts a simulated world of its own ({@link SimulatorCamera}); the
 * simulator view hands in the camera of a robot in its world instead. {@link #NOT_AVAILABLE} is a
 * hook for programs that want File → Simulator Camera to explain that there is none.
 */
@FunctionalInterface
public interface SimCameraHook {

  /**
   * Opens the simulator's camera at the working size.
   *
   * @throws IOException if there is no simulated camera (the message says what to do instead)
   */
  ImageSource open(int width, int height) throws IOException;

  /** A hook for when there is no simulator to look through: explains and fails. */
  SimCameraHook NOT_AVAILABLE =
      (w, h) -> {
        throw new IOException(
            "The simulator's camera is not connected to EZ-Train in this build. Train on a still"
                + " image (File → Load Image) or a real camera (File → Live Video) instead; a"
                + " program can pass any ImageSource to EzTrainWindow.useVideoSource().");
      };
}
