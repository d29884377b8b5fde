package org.jaria.acts.image;

/**
 * A live camera (or a video file read like one): frames as they come, and the camera's own
 * settings. {@link Cameras#open} opens one through the camera driver on the class path.
 */
public interface LiveCamera extends ImageSource {

  /**
   * Sets a camera parameter by name (the names {@link Cameras#parameterList()} lists).
   *
   * @return whether the camera accepted it
   * @throws IllegalArgumentException if the name is unknown
   */
  boolean setParameter(String name, double value);
}
