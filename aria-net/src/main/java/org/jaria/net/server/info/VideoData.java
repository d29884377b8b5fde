package org.jaria.net.server.info;

import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.RequestHandler;
import org.jaria.net.server.Where;

/**
 * ArNetworking's two video data, {@code "videoSize"} and {@code "sendVideo"}, declared once with
 * the names, descriptions, group and flags ARIA's clients (getVideoExample, MobileEyes) look for,
 * whether the pictures come from a camera here ({@link ArServerHandlerVideo}) or from another
 * server ({@code ArHybridForwarderVideo}).
 */
public final class VideoData {

  private VideoData() {}

  /** Registers {@code "videoSize"}: answers width and height as two {@code uByte2}. */
  public static void addVideoSize(ArServerBase server, RequestHandler handler) {
    server.addData(
        "videoSize",
        "gets the width and height of the video data",
        "none",
        "uByte2: width, uByte2: height",
        "Video",
        "RETURN_SINGLE",
        Where.WORKER,
        handler);
  }

  /** Registers {@code "sendVideo"}: answers width, height and a JPEG picture in one packet. */
  public static void addSendVideo(ArServerBase server, RequestHandler handler) {
    server.addData(
        "sendVideo",
        "gets video from the robot's camera (you should requestOnce this, you shouldn't request"
            + " it, since you could easily fill the bandwidth that way)",
        "uByte: quality (0 - 100)",
        "out: uByte2: width, uByte2: height, (len - readLen)*uByte: jpegData",
        "Video",
        "RETURN_VIDEO",
        Where.WORKER,
        handler);
  }
}
