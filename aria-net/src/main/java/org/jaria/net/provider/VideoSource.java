package org.jaria.net.provider;

import org.jaria.net.data.VideoFrame;

/**
 * A camera for the network server (ArNetworking's video forwarding; ACTS or a camera through an
 * adapter). {@link #getLatestFrame()} is called on the server's publisher thread at the clients'
 * rates: return the newest frame already captured, never wait for one.
 */
public interface VideoSource {

  /** The camera's name ("Cam1"). */
  String getName();

  /** The newest frame, or null if none yet; a new frame has a new sequence number. */
  VideoFrame getLatestFrame();
}
