package org.jaria.net.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.junit.jupiter.api.Test;

/**
 * The server's frame decoder: frames arriving in pieces of any size come out whole and in order;
 * random bytes never make it throw anything but a {@link ProtocolException}, never loop, and never
 * make it hold more than one largest frame.
 */
class FrameSplitterTest {

  private static final int MAX = 64 * 1024;

  /** Feeds {@code stream} in random pieces; returns the frames' bodies. */
  private static List<byte[]> split(FrameSplitter s, byte[] stream, Random rnd)
      throws ProtocolException {
    List<byte[]> out = new ArrayList<>();
    split(s, stream, rnd, (a, off, len) -> out.add(Arrays.copyOfRange(a, off, off + len)));
    return out;
  }

  /** Feeds {@code stream} in random pieces to {@code s}, which hands frames to {@code sink}. */
  private static void split(FrameSplitter s, byte[] stream, Random rnd, FrameSplitter.Sink sink)
      throws ProtocolException {
    int pos = 0;
    while (pos < stream.length) {
      ByteBuffer b = s.buffer();
      int n = Math.min(stream.length - pos, 1 + rnd.nextInt(Math.min(b.remaining(), 9000)));
      b.put(stream, pos, n);
      pos += n;
      s.drain(sink);
      assertTrue(s.capacity() <= MAX + Protocol.LENGTH_BYTES, "never more than one frame held");
      assertTrue(s.buffer().hasRemaining(), "room for the next read");
    }
  }

  @Test
  void framesInPiecesComeOutWholeAndInOrder() throws Exception {
    Random rnd = new Random(7);
    for (int round = 0; round < 200; round++) {
      ByteArrayOutputStream stream = new ByteArrayOutputStream();
      List<byte[]> bodies = new ArrayList<>();
      int frames = 1 + rnd.nextInt(20);
      for (int i = 0; i < frames; i++) {
        byte[] data = new byte[rnd.nextInt(rnd.nextBoolean() ? 50 : 20_000)];
        rnd.nextBytes(data);
        byte[] f = Frames.frame(Kind.CALL, i, 1, data);
        bodies.add(Arrays.copyOfRange(f, Protocol.LENGTH_BYTES, f.length));
        stream.writeBytes(f);
      }
      List<byte[]> got = split(new FrameSplitter(64, MAX), stream.toByteArray(), rnd);
      assertEquals(bodies.size(), got.size());
      for (int i = 0; i < got.size(); i++) {
        assertArrayEquals(bodies.get(i), got.get(i), "frame " + i + " of round " + round);
      }
    }
  }

  @Test
  void randomBytesOnlyEverGiveProtocolErrors() {
    Random rnd = new Random(11);
    int refused = 0;
    int[] decodedFrames = {0};
    for (int round = 0; round < 5000; round++) {
      byte[] garbage = new byte[1 + rnd.nextInt(rnd.nextInt(10) == 0 ? 70_000 : 300)];
      rnd.nextBytes(garbage);
      if (garbage.length >= 4 && rnd.nextBoolean()) {
        // A plausible length prefix, so the bytes after it reach the message decoder.
        ByteBuffer.wrap(garbage).putInt(0, Math.max(1, rnd.nextInt(garbage.length + 8)));
      }
      FrameSplitter s = new FrameSplitter(16, MAX);
      try {
        split(
            s,
            garbage,
            rnd,
            (a, off, len) -> {
              decodedFrames[0]++;
              decodeLikeTheServer(Arrays.copyOfRange(a, off, off + len));
            });
      } catch (ProtocolException e) {
        refused++;
        assertTrue(e.getMessage() != null && !e.getMessage().isEmpty());
      }
    }
    assertTrue(refused > 2500, "most garbage is refused: " + refused);
    assertTrue(
        decodedFrames[0] > 500, "and much of it reached the message decoder: " + decodedFrames[0]);
  }

  /** What the dispatcher does with a frame: kind, then every value, strictly. */
  private static void decodeLikeTheServer(byte[] frame) throws ProtocolException {
    try {
      ArNetPacket p = ArNetPacket.wrap(frame);
      Kind k = Kind.fromCode(p.bufToLong());
      if (k == null) {
        throw new ProtocolException(NetError.MALFORMED, "unknown frame kind");
      }
      p.validate();
      while (p.hasMore()) {
        p.bufToValue();
      }
    } catch (ArNetPacketException e) {
      throw new ProtocolException(NetError.MALFORMED, e.getMessage(), e);
    }
  }

  @Test
  void oversizedOrEmptyFramesAreRefusedBeforeBuffering() {
    FrameSplitter s = new FrameSplitter(16, MAX);
    s.buffer().putInt(MAX + 1);
    ProtocolException e = assertThrows(ProtocolException.class, () -> s.drain((a, o, l) -> {}));
    assertEquals(NetError.MALFORMED, e.getCode());
    assertEquals(16, s.capacity(), "nothing allocated for the announced frame");
    FrameSplitter z = new FrameSplitter(16, MAX);
    z.buffer().putInt(0);
    assertThrows(ProtocolException.class, () -> z.drain((a, o, l) -> {}));
  }

  @Test
  void aLargeAllowedFrameGrowsTheBufferOnce() throws Exception {
    FrameSplitter s = new FrameSplitter(16, MAX);
    byte[] f = Frames.frame(Kind.CALL, 1, 2, new byte[40_000]);
    List<byte[]> got = split(s, f, new Random(3));
    assertEquals(1, got.size());
    assertEquals(f.length - Protocol.LENGTH_BYTES, got.get(0).length);
    assertEquals(0, s.pendingBytes());
  }
}
