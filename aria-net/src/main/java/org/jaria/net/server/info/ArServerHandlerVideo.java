package org.jaria.net.server.info;

import org.jaria.net.data.VideoFrame;
import org.jaria.net.provider.VideoSource;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;
import org.jaria.net.server.Where;
import org.jaria.net.video.AriaJpeg;

/**
 * Video for clients (ArNetworking's video forwarding and its video server's data): {@code
 * "getVideo"} publishes the source's newest frame (a slow client gets fewer frames, never a
 * backlog; JAria's layout), {@code "getVideoInfo"} names the camera, and ArNetworking's {@code
 * "sendVideo"} and {@code "videoSize"} answer a JPEG in ARIA's layout (see {@link AriaJpeg}). The
 * camera's pan, tilt and zoom are {@link ArServerHandlerCamera}'s.
 */
public final class ArServerHandlerVideo {

  /** Registers the video data with {@code server}. */
  public ArServerHandlerVideo(ArServerBase server, VideoSource source) {
    server.addPublishedData(
        "getVideo",
        "the newest camera frame: subscribe at the frame rate you want",
        "VideoFrame [sequence, format JPEG|PNG|RGB, width, height, bytes]",
        "Video",
        PolledPublication.keyed(
            () -> {
              VideoFrame f = source.getLatestFrame();
              return f == null ? Long.MIN_VALUE : f.getSequence();
            },
            source::getLatestFrame));
    server.addData(
        "getVideoInfo",
        "the camera's name",
        "none",
        "string name",
        "Video",
        Where.WORKER,
        (client, request, reply) -> reply.strToBuf(source.getName()));
    // ArNetworking's video data (ArHybridForwarderVideo, getVideoExample): JPEG in one packet.
    VideoData.addSendVideo(
        server,
        (client, request, reply) ->
            AriaJpeg.write(
                source.getLatestFrame(), request.hasMore() ? request.bufToUByte() : 75, reply));
    VideoData.addVideoSize(
        server,
        (client, request, reply) -> {
          VideoFrame f = source.getLatestFrame();
          reply
              .uByte2ToBuf(f == null ? 0 : f.getWidth())
              .uByte2ToBuf(f == null ? 0 : f.getHeight());
        });
  }
}
