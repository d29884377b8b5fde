package org.jaria.simguiserver;

import org.jaria.net.video.JpegVideo;
import org.jaria.sim.camera.SimCamera;

/**
 * The simulated camera as the server's video (what a real robot's camera or ACTS would give): the
 * camera's view rendered and compressed to JPEG a few times a second while someone watches.
 */
public final class SimCameraVideo extends JpegVideo {

  /**
   * Video from {@code camera}.
   *
   * @param framesPerSecond how often a frame is made while watched
   */
  public SimCameraVideo(SimCamera camera, String name, double framesPerSecond) {
    super(
        name,
        camera.getWidth(),
        camera.getHeight(),
        framesPerSecond,
        rgb -> {
          camera.render(rgb);
          return true;
        });
  }
}
