package org.jaria.net.forward;

/**
 * Whether the body of a video packet from a video server ({@code sendVideo}: ubyte2 width, ubyte2
 * height, then a JPEG to the end; {@code videoSize}: ubyte2 width, ubyte2 height) is something a
 * forwarder may pass on to its own clients. A server that sends anything else is not a video
 * server, or a broken one: its packet is dropped and counted, and clients keep the previous frame.
 */
public final class VideoPacketCheck {

  /** Largest width or height accepted (pixels): bigger than any camera of the era. */
  public static final int MAX_SIDE = 8192;

  private VideoPacketCheck() {}

  /**
   * Why {@code body} is not a frame, or null if it is one. A 0 × 0 frame with no bytes is a frame:
   * it is how a video server says it has no picture yet.
   */
  public static String whyNotAFrame(byte[] body) {
    String size = whyNotASize(body);
    if (size != null) {
      return size;
    }
    int w = side(body, 0);
    int h = side(body, 2);
    int jpeg = body.length - 4;
    if (w == 0 && h == 0) {
      return jpeg == 0 ? null : "a 0 x 0 frame with " + jpeg + " bytes";
    }
    if (w == 0 || h == 0) {
      return "a frame of " + w + " x " + h + " pixels";
    }
    if (jpeg < 4 || (body[4] & 0xff) != 0xff || (body[5] & 0xff) != 0xd8) {
      return "a " + w + " x " + h + " frame whose bytes are not a JPEG";
    }
    return null;
  }

  /** Why {@code body} is not a video size, or null if it is one. */
  public static String whyNotASize(byte[] body) {
    if (body.length < 4) {
      return "a video packet of " + body.length + " bytes (it needs at least a width and height)";
    }
    int w = side(body, 0);
    int h = side(body, 2);
    if (w > MAX_SIDE || h > MAX_SIDE) {
      return "a video size of " + w + " x " + h + " pixels";
    }
    return null;
  }

  private static int side(byte[] b, int at) {
    return (b[at] & 0xff) | (b[at + 1] & 0xff) << 8;
  }
}
