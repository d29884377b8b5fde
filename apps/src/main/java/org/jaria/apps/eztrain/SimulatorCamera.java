package org.jaria.apps.eztrain;

import java.io.IOException;
import java.util.function.Consumer;
import org.jaria.acts.image.ImageSource;
import org.jaria.simvision.TrainingScene;

/**
 * EZ-Train's own simulator camera (File → Simulator Camera when EZ-Train runs on its own): starts
 * the {@link TrainingScene} — a simulated robot in the hall with coloured things in front of its
 * camera — in real time, and trains on what the camera sees. The robot listens on a TCP port (8101
 * unless told otherwise), so a program can drive it and, through EZ-Train's ACTS server, track the
 * colours being trained; closing the video (another source, or the window) stops the world.
 */
final class SimulatorCamera implements SimCameraHook {

  private final int port;
  private final Consumer<String> log;
  private volatile TrainingScene scene;

  /**
   * @param port the robot's TCP port (0: any free port; -1: do not listen)
   * @param log where to say which port the robot listens on (any thread)
   */
  SimulatorCamera(int port, Consumer<String> log) {
    this.port = port;
    this.log = log;
  }

  @Override
  public ImageSource open(int width, int height) throws IOException {
    TrainingScene s = TrainingScene.create(Math.max(0, port));
    try {
      if (port >= 0) {
        try {
          int p = s.listen();
          log.accept(
              "Simulated robot listening on TCP port "
                  + p
                  + ": drive it with an ARIA program (-remoteRobotTcpPort "
                  + p
                  + ") and the camera follows");
        } catch (IOException e) {
          log.accept(
              "The simulated robot does not listen ("
                  + e.getMessage()
                  + "); the camera works all the same");
        }
      }
      s.start();
      ImageSource camera = s.camera(width, height);
      scene = s;
      return new ImageSource() {
        @Override
        public int width() {
          return camera.width();
        }

        @Override
        public int height() {
          return camera.height();
        }

        @Override
        public boolean nextFrame(int[] rgb) throws IOException {
          return camera.nextFrame(rgb);
        }

        @Override
        public String describe() {
          return "the simulator's camera (hall, " + width() + "x" + height() + ")";
        }

        @Override
        public void close() {
          camera.close();
          s.close();
        }
      };
    } catch (RuntimeException e) {
      s.close();
      throw e;
    }
  }

  /** The scene last opened (tests drive its robot), or null. */
  TrainingScene scene() {
    return scene;
  }
}
