package org.jaria.acts.camera;

import java.io.IOException;
import org.jaria.acts.image.CameraDriver;
import org.jaria.acts.image.LiveCamera;

/**
 * The camera driver through OpenCV ({@link CameraSource}), found by {@code
 * org.jaria.acts.image.Cameras} when this module is on the class path.
 */
public final class OpenCvCameras implements CameraDriver {

  /** Used by {@link java.util.ServiceLoader}. */
  public OpenCvCameras() {}

  @Override
  public LiveCamera open(String device, int width, int height) throws IOException {
    return CameraSource.open(device, width, height);
  }

  @Override
  public String parameterList() {
    return CameraSource.parameterList();
  }
}
