package org.jaria.simvision;

import org.jaria.acts.image.ImageSource;
import org.jaria.sim.camera.SimCamera;

/** The simulated camera as an ACTS image source: each frame is what the camera sees now. */
public final class SimCameraSource implements ImageSource {

  private final SimCamera camera;

  /** Frames from {@code camera}. */
  public SimCameraSource(SimCamera camera) {
    this.camera = camera;
  }

  @Override
  public int width() {
    return camera.getWidth();
  }

  @Override
  public int height() {
    return camera.getHeight();
  }

  @Override
  public boolean nextFrame(int[] rgb) {
    camera.render(rgb);
    return true;
  }

  @Override
  public String describe() {
    return "simulated camera " + width() + "x" + height();
  }
}
