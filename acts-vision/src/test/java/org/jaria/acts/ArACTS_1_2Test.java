package org.jaria.acts;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import org.jaria.clock.Clock;
import org.jaria.connection.PipeConnection;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The client's parser against byte vectors computed by hand from the protocol description. */
class ArACTS_1_2Test {

  private PipeConnection server;
  private ArACTS_1_2 acts;

  @BeforeEach
  void connect() throws IOException {
    PipeConnection.Pair pair = PipeConnection.pair(Clock.system(), "acts");
    server = pair.b();
    server.open();
    acts = new ArACTS_1_2();
    assertTrue(acts.openPort(pair.a()));
    acts.setReadTimeouts(2000, 2000);
  }

  /** Header: channel c's 4 bytes; all others empty with the given running index. */
  private static byte[] header(int... indexCountPairsByChannel) {
    byte[] h = new byte[128];
    for (int c = 0; c < 32; c++) {
      int index = indexCountPairsByChannel[2 * c];
      int count = indexCountPairsByChannel[2 * c + 1];
      h[4 * c] = (byte) ((index >> 6) + 1);
      h[4 * c + 1] = (byte) ((index & 63) + 1);
      h[4 * c + 2] = (byte) ((count >> 6) + 1);
      h[4 * c + 3] = (byte) ((count & 63) + 1);
    }
    return h;
  }

  private static int[] pairs(int... channelIndexCount) {
    int[] p = new int[64];
    for (int i = 0; i < channelIndexCount.length; i += 3) {
      p[2 * (channelIndexCount[i] - 1)] = channelIndexCount[i + 1];
      p[2 * (channelIndexCount[i] - 1) + 1] = channelIndexCount[i + 2];
    }
    return p;
  }

  private void send(byte[]... parts) throws IOException {
    for (byte[] p : parts) {
      server.write(p, 0, p.length);
    }
  }

  @Test
  void requestsAreTheBytesZeroAndOne() throws IOException {
    assertTrue(acts.requestPacket());
    assertTrue(acts.requestQuit());
    byte[] b = new byte[2];
    assertEquals(2, server.read(b, 0, 2, 1000));
    assertEquals('0', b[0]);
    assertEquals('1', b[1]);
  }

  @Test
  void parsesAReplyWithBlobsOnTwoChannels() throws IOException {
    // Channel 1: one blob; channel 3: two blobs (indices 1 and 2).
    byte[] h = header(pairs(1, 0, 1, 3, 1, 2));
    // Blob 0: area 1234 -> 0,0,19,18; xcg 80 -> 1,16; ycg 60 -> 0,60; l 70 -> 1,6;
    // r 90 -> 1,26; t 50 -> 0,50; b 70 -> 1,6. Each digit + 1.
    byte[] b0 = {1, 1, 20, 19, 2, 17, 1, 61, 2, 7, 2, 27, 1, 51, 2, 7};
    // Blob 1: area 4096 -> 0,1,0,0; everything else 64 -> 1,0.
    byte[] b1 = {1, 2, 1, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1};
    // Blob 2: area 65 -> 0,0,1,1; xcg 0; ycg 4095 -> 63,63; l 1; r 2; t 3; b 119 -> 1,55.
    byte[] b2 = {1, 1, 2, 2, 1, 1, 64, 64, 1, 2, 1, 3, 1, 4, 2, 56};
    send(h, b0, b1, b2);
    assertTrue(acts.receiveBlobInfo());
    assertEquals(1, acts.getNumBlobs(1));
    assertEquals(0, acts.getNumBlobs(2));
    assertEquals(2, acts.getNumBlobs(3));
    assertEquals(-1, acts.getNumBlobs(0));
    assertEquals(-1, acts.getNumBlobs(33));
    ArACTSBlob blob = new ArACTSBlob();
    assertTrue(acts.getBlob(1, 1, blob));
    assertEquals("Area: 1234 X:  80 Y:  60 l:  70 r:  90 t:  50: b:  70", blob.toString());
    assertTrue(acts.getBlob(3, 1, blob));
    assertEquals(4096, blob.getArea());
    assertEquals(64, blob.getXCG());
    assertEquals(64, blob.getBottom());
    assertTrue(acts.getBlob(3, 2, blob));
    assertEquals(65, blob.getArea());
    assertEquals(0, blob.getXCG());
    assertEquals(4095, blob.getYCG());
    assertEquals(1, blob.getLeft());
    assertEquals(2, blob.getRight());
    assertEquals(3, blob.getTop());
    assertEquals(119, blob.getBottom());
    assertFalse(acts.getBlob(3, 3, blob), "out of range");
    assertFalse(acts.getBlob(2, 1, blob), "channel 2 has none");
    assertFalse(acts.getBlob(0, 1, blob));
  }

  @Test
  void anEmptyReplyIsValid() throws IOException {
    send(header(new int[64]));
    assertTrue(acts.receiveBlobInfo());
    for (int c = 1; c <= 32; c++) {
      assertEquals(0, acts.getNumBlobs(c));
    }
  }

  @Test
  void aReplyArrivingInPiecesIsAssembledAcrossCalls() throws IOException {
    acts.setReadTimeouts(0, 0);
    byte[] h = header(pairs(2, 0, 1));
    byte[] b0 = {1, 1, 1, 11, 1, 3, 1, 4, 1, 2, 1, 5, 1, 2, 1, 7};
    send(java.util.Arrays.copyOf(h, 50));
    assertFalse(acts.receiveBlobInfo(), "header incomplete");
    send(java.util.Arrays.copyOfRange(h, 50, 128), java.util.Arrays.copyOf(b0, 5));
    assertFalse(acts.receiveBlobInfo(), "blob incomplete");
    assertFalse(acts.getBlob(2, 1, new ArACTSBlob()), "no valid data yet");
    send(java.util.Arrays.copyOfRange(b0, 5, 16));
    assertTrue(acts.receiveBlobInfo());
    ArACTSBlob blob = new ArACTSBlob();
    assertTrue(acts.getBlob(2, 1, blob));
    assertEquals(10, blob.getArea());
    assertEquals(6, blob.getBottom());
  }

  @Test
  void invalidDigitsAreRejectedAndTheStreamRecovers() throws IOException {
    byte[] h = header(new int[64]);
    h[7] = 0; // not a digit
    send(h);
    assertFalse(acts.receiveBlobInfo());
    assertEquals(1, acts.getProtocolErrors());
    byte[] tooMany = header(pairs(1, 0, 11));
    send(tooMany);
    assertFalse(acts.receiveBlobInfo());
    assertEquals(2, acts.getProtocolErrors());
    byte[] pastEnd = header(pairs(1, 5, 1));
    send(pastEnd, new byte[16]);
    assertFalse(acts.receiveBlobInfo());
    assertEquals(3, acts.getProtocolErrors());
    send(header(pairs(4, 0, 1)), new byte[] {1, 1, 1, 2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1});
    assertTrue(acts.receiveBlobInfo(), "a good reply after bad ones is read");
    assertEquals(1, acts.getNumBlobs(4));
  }

  @Test
  void badBlobBytesAreRejected() throws IOException {
    byte[] b = new byte[16];
    java.util.Arrays.fill(b, (byte) 1);
    b[9] = (byte) 200;
    send(header(pairs(1, 0, 1)), b);
    assertFalse(acts.receiveBlobInfo());
    assertEquals(1, acts.getProtocolErrors());
  }

  @Test
  void invertFlipsCoordinatesLikeAria() throws IOException {
    acts.invert(160, 120);
    send(header(pairs(1, 0, 1)), new byte[] {1, 1, 1, 11, 1, 11, 1, 21, 1, 1, 1, 31, 1, 1, 1, 2});
    assertTrue(acts.receiveBlobInfo());
    ArACTSBlob blob = new ArACTSBlob();
    acts.getBlob(1, 1, blob);
    assertEquals(10, blob.getArea());
    assertEquals(150, blob.getXCG());
    assertEquals(100, blob.getYCG());
    assertEquals(160, blob.getLeft());
    assertEquals(130, blob.getRight());
    assertEquals(120, blob.getTop());
    assertEquals(119, blob.getBottom());
  }

  @Test
  void actsHandlerRequestsAgainOnceAnswered() throws IOException {
    byte[] b = new byte[4];
    acts.actsHandler(); // first call: requests
    assertEquals(1, server.read(b, 0, 4, 1000));
    acts.setReadTimeouts(0, 0);
    acts.actsHandler(); // no reply yet: does not request again
    assertEquals(0, server.read(b, 0, 4, 0));
    send(header(new int[64]));
    acts.actsHandler(); // reply read: requests the next
    assertEquals(1, server.read(b, 0, 4, 1000));
  }

  @Test
  void closedConnectionAndRefusedPort() throws IOException {
    server.close();
    assertFalse(acts.receiveBlobInfo());
    acts.closePort();
    assertFalse(acts.isConnected());
    assertFalse(acts.requestPacket());
    int free;
    try (ServerSocket s = new ServerSocket(0)) {
      free = s.getLocalPort();
    }
    ArACTS_1_2 other = new ArACTS_1_2();
    assertFalse(other.openPort("127.0.0.1", free));
    assertTrue(
        other.getOpenMessage().contains("could not connect to ACTS at 127.0.0.1:" + free),
        other.getOpenMessage());
    assertTrue(other.getOpenMessage().contains("./jaria acts"));
  }
}
