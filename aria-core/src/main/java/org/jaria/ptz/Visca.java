package org.jaria.ptz;

/**
 * Sony VISCA command bytes for the EVI-D30/D70 as ARIA drives it: every command starts with 0x81
 * (camera 1) or 0x88 (broadcast) and ends with 0xFF; 16-bit values travel as four bytes of one
 * nibble each, most significant first.
 */
public final class Visca {

  private Visca() {}

  /** Pan speed ARIA uses (of 0x01–0x18). */
  public static final int PAN_SPEED = 0x18;

  /** Tilt speed ARIA uses (of 0x01–0x14). */
  public static final int TILT_SPEED = 0x14;

  /** Broadcast "clear interfaces" then "set address", sent once at start-up. */
  public static byte[] init() {
    return bytes(0x88, 0x01, 0x00, 0x01, 0xff, 0x88, 0x30, 0x01, 0xff);
  }

  /** Absolute pan-tilt to {@code pan}, {@code tilt} in the camera's units (signed). */
  public static byte[] panTilt(int pan, int tilt) {
    byte[] b = new byte[15];
    int[] head = {0x81, 0x01, 0x06, 0x02, PAN_SPEED, TILT_SPEED};
    for (int i = 0; i < head.length; i++) {
      b[i] = (byte) head[i];
    }
    nibbles(b, 6, pan);
    nibbles(b, 10, tilt);
    b[14] = (byte) 0xff;
    return b;
  }

  /** Direct zoom to {@code value} (0..1023). */
  public static byte[] zoom(int value) {
    byte[] b = {(byte) 0x81, 0x01, 0x04, 0x47, 0, 0, 0, 0, (byte) 0xff};
    nibbles(b, 4, value);
    return b;
  }

  /** Pan-tilt position inquiry; the camera answers {@code 90 50} + 8 nibbles + {@code FF}. */
  public static byte[] panTiltInquiry() {
    return bytes(0x81, 0x09, 0x06, 0x12, 0xff);
  }

  /** Zoom position inquiry; the camera answers {@code 90 50} + 4 nibbles + {@code FF}. */
  public static byte[] zoomInquiry() {
    return bytes(0x81, 0x09, 0x04, 0x47, 0xff);
  }

  /** Bytes a camera answers to a command: acknowledge and completion, 3 bytes each. */
  public static final int COMMAND_REPLY_BYTES = 6;

  /** Bytes the two broadcasts of {@link #init()} come back as (5 + 4). */
  public static final int INIT_REPLY_BYTES = 9;

  /** Bytes of the answer to {@link #panTiltInquiry()}. */
  public static final int PAN_TILT_ANSWER_BYTES = 11;

  /** Bytes of the answer to {@link #zoomInquiry()}. */
  public static final int ZOOM_ANSWER_BYTES = 7;

  /** Back-lighting compensation on or off. */
  public static byte[] backLight(boolean on) {
    return bytes(0x81, 0x01, 0x04, 0x33, on ? 0x02 : 0x03, 0xff);
  }

  private static void nibbles(byte[] b, int at, int value) {
    int v = value & 0xffff;
    b[at] = (byte) ((v >> 12) & 0xf);
    b[at + 1] = (byte) ((v >> 8) & 0xf);
    b[at + 2] = (byte) ((v >> 4) & 0xf);
    b[at + 3] = (byte) (v & 0xf);
  }

  private static byte[] bytes(int... v) {
    byte[] b = new byte[v.length];
    for (int i = 0; i < v.length; i++) {
      b[i] = (byte) v[i];
    }
    return b;
  }
}
