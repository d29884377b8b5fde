package org.jaria.acts.server;

import org.jaria.acts.ActsProtocol;
import org.jaria.acts.blob.BlobFrame;

/**
 * A tracker's frame as the ACTS server's reply to a client's {@code '0'}: the header of channel
 * indices and counts, then every blob, in the layout {@link ActsProtocol} describes.
 */
public final class ActsReply {

  private ActsReply() {}

  /**
   * Encodes a frame's blobs as a reply.
   *
   * @param out at least {@link ActsProtocol#MAX_REPLY} bytes
   * @return the reply length
   */
  public static int encode(BlobFrame frame, byte[] out) {
    int index = 0;
    int pos = ActsProtocol.HEADER_SIZE;
    for (int ch = 1; ch <= ActsProtocol.NUM_CHANNELS; ch++) {
      int n = frame.getNumBlobs(ch);
      ActsProtocol.putNumber(index, 2, out, (ch - 1) * 4);
      ActsProtocol.putNumber(n, 2, out, (ch - 1) * 4 + 2);
      for (int b = 1; b <= n; b++) {
        var blob = frame.getBlob(ch, b);
        ActsProtocol.putNumber(blob.area(), 4, out, pos);
        ActsProtocol.putNumber(blob.xcg(), 2, out, pos + 4);
        ActsProtocol.putNumber(blob.ycg(), 2, out, pos + 6);
        ActsProtocol.putNumber(blob.left(), 2, out, pos + 8);
        ActsProtocol.putNumber(blob.right(), 2, out, pos + 10);
        ActsProtocol.putNumber(blob.top(), 2, out, pos + 12);
        ActsProtocol.putNumber(blob.bottom(), 2, out, pos + 14);
        pos += ActsProtocol.BLOB_SIZE;
      }
      index += n;
    }
    return pos;
  }

  /** Encodes a frame's blobs as a new reply array of exactly the reply's length. */
  public static byte[] encode(BlobFrame frame) {
    byte[] buf = new byte[ActsProtocol.MAX_REPLY];
    int n = encode(frame, buf);
    byte[] out = new byte[n];
    System.arraycopy(buf, 0, out, 0, n);
    return out;
  }
}
