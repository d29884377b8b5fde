package org.jaria.acts;

/**
 * The ACTS server's wire protocol, as ARIA's {@code ArACTS_1_2} client expects it.
 *
 * <ul>
 *   <li>TCP, default port {@value #DEFAULT_PORT}. The client writes one byte: {@code '0'} asks for
 *       the current blob data, {@code '1'} asks ACTS to quit.
 *   <li>Every number is sent as base-64 digits, most significant first, each digit {@code d} sent
 *       as the byte {@code d + 1} (so no byte is ever 0): a 2-digit number is 0..4095, a 4-digit
 *       one 0..16,777,215.
 *   <li>The reply starts with a {@value #HEADER_SIZE}-byte header: for each of the 32 channels the
 *       index of its first blob among all blobs of the reply (2 digits) and its blob count (2
 *       digits).
 *   <li>Then, for every blob in channel order, {@value #BLOB_SIZE} bytes: area (4 digits), then
 *       xcg, ycg, left, right, top, bottom (2 digits each), in image pixel coordinates. ({@code
 *       org.jaria.acts.server.ActsReply} writes a tracker's frame this way.)
 * </ul>
 *
 * <p>Worked example: a reply with one blob on channel 1 of area 1234, centre (80, 60), box columns
 * 70..90 and rows 50..70 is the header {@code 01 01 01 02} (index 0, count 1) followed by 31 ×
 * {@code 01 02 01 01} (index 1, count 0), then the blob {@code 01 01 14 13 | 02 11 | 01 3D | 02 07
 * | 02 1B | 01 33 | 02 07} (1234 = 19·64 + 18; 80 = 1·64 + 16; ...), each byte shown in
 * hexadecimal. The index of a channel is the number of blobs of the channels before it.
 */
public final class ActsProtocol {

  /** ACTS's default TCP port. */
  public static final int DEFAULT_PORT = 5001;

  /** The request byte for the current blob data. */
  public static final byte REQUEST_PACKET = '0';

  /** The request byte asking ACTS to quit. */
  public static final byte REQUEST_QUIT = '1';

  /** Number of channels in a reply. */
  public static final int NUM_CHANNELS = 32;

  /** Most blobs per channel. */
  public static final int MAX_BLOBS = 10;

  /** Bytes of the reply header (4 per channel). */
  public static final int HEADER_SIZE = NUM_CHANNELS * 4;

  /** Bytes per blob. */
  public static final int BLOB_SIZE = 16;

  /** Largest possible reply: the header and 10 blobs on each of the 32 channels. */
  public static final int MAX_REPLY = HEADER_SIZE + NUM_CHANNELS * MAX_BLOBS * BLOB_SIZE;

  /** Largest value of a 2-digit number. */
  public static final int MAX_2_DIGITS = (1 << 12) - 1;

  /** Largest value of a 4-digit number. */
  public static final int MAX_4_DIGITS = (1 << 24) - 1;

  private ActsProtocol() {}

  /**
   * Writes {@code value} as {@code digits} base-64 digits, each plus one. Values that do not fit
   * are clamped to the largest that does (only an area above 16.7 million pixels could).
   */
  public static void putNumber(int value, int digits, byte[] out, int off) {
    int max = (1 << (6 * digits)) - 1;
    int v = Math.max(0, Math.min(max, value));
    for (int i = digits - 1; i >= 0; i--) {
      out[off + i] = (byte) ((v & 63) + 1);
      v >>>= 6;
    }
  }

  /**
   * Reads a number of {@code digits} base-64 digits.
   *
   * @return the value, or -1 if a byte is not a valid digit (1..64)
   */
  public static int getNumber(byte[] in, int off, int digits) {
    int v = 0;
    for (int i = 0; i < digits; i++) {
      int d = (in[off + i] & 0xFF) - 1;
      if (d < 0 || d > 63) {
        return -1;
      }
      v = (v << 6) | d;
    }
    return v;
  }
}
