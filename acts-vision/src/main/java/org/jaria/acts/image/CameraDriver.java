package org.jaria.acts.image;

import java.io.IOException;

/**
 * Opens live cameras. This library reads no camera itself, so that a program that only speaks the
 * ACTS protocol, tracks still images or the simulator's camera needs no native video library; the
 * module {@code acts-camera} provides a driver through OpenCV, which {@link Cameras} finds with
 * {@link java.util.ServiceLoader}.
 */
public interface CameraDriver {

  /**
   * Opens a camera or a video file, frames scaled to {@code width × height}.
   *
   * @param device a camera index ({@code -1} = the first camera) or a device or video file path
   * @throws IOException if there is no such camera or file, or it cannot be opened (the message
   *     says what to try instead)
   */
  LiveCamera open(String device, int width, int height) throws IOException;

  /** The parameter names a camera takes, one per line with a heading (ACTS's {@code -P}). */
  String parameterList();
}
