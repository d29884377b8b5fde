package org.jaria.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class ArRobotPacketReceiverTest {

  private final DropCounters drops = new DropCounters("test");
  private final ArRobotPacketReceiver receiver = new ArRobotPacketReceiver(drops);
  private final List<byte[]> got = new ArrayList<>();
  private final ArRobotPacketReceiver.Listener collect = p -> got.add(p.toByteArray());

  private static byte[] packet(int id, int... data) {
    ArRobotPacket p = new ArRobotPacket(id);
    for (int d : data) {
      p.uByteToBuf(d);
    }
    return p.finalizePacket().toByteArray();
  }

  private void feed(byte[] b, long now) {
    receiver.feed(b, 0, b.length, now, collect);
  }

  @Test
  void wholePacketIsDelivered() {
    byte[] p = packet(0x32, 1, 2, 3);
    feed(p, 0);
    assertEquals(1, got.size());
    assertArrayEquals(p, got.get(0));
    assertEquals(0, drops.total());
  }

  @Test
  void packetSplitIntoSingleBytesIsDelivered() {
    byte[] p = packet(0x20, 9, 8, 7, 6);
    for (int i = 0; i < p.length; i++) {
      receiver.feed(p, i, 1, i, collect);
    }
    assertEquals(1, got.size());
    assertArrayEquals(p, got.get(0));
  }

  @Test
  void garbageBeforeAPacketIsSkippedAndCounted() {
    byte[] p = packet(0x90, 1, 2, 3, 4, 5, 6, 7, 8);
    ByteArrayOutputStream s = new ByteArrayOutputStream();
    s.writeBytes(new byte[] {1, 2, (byte) 0xFA, 7, (byte) 0xFB});
    s.writeBytes(p);
    feed(s.toByteArray(), 0);
    assertEquals(1, got.size());
    assertArrayEquals(p, got.get(0));
    assertEquals(5, drops.skippedBytes());
  }

  @Test
  void badChecksumIsDroppedAndTheNextPacketFound() {
    byte[] bad = packet(0x32, 1, 2, 3);
    bad[bad.length - 1] ^= 1;
    byte[] good = packet(0x33, 4, 5);
    feed(bad, 0);
    feed(good, 0);
    assertEquals(1, got.size());
    assertArrayEquals(good, got.get(0));
    assertEquals(1, drops.get(DropReason.BAD_CHECKSUM));
  }

  @Test
  void countAbove204IsRejected() {
    byte[] good = packet(0x33, 4, 5);
    ByteArrayOutputStream s = new ByteArrayOutputStream();
    s.writeBytes(new byte[] {(byte) 0xFA, (byte) 0xFB, (byte) 205, 1, 2});
    s.writeBytes(good);
    feed(s.toByteArray(), 0);
    assertEquals(1, got.size());
    assertEquals(1, drops.get(DropReason.BAD_LENGTH));
  }

  @Test
  void validPacketHiddenInsideABogusLongCandidateIsFound() {
    // A fake header claims 100 bytes; a real packet follows within those bytes.
    byte[] good = packet(0x32, 1, 2, 3);
    ByteArrayOutputStream s = new ByteArrayOutputStream();
    s.writeBytes(new byte[] {(byte) 0xFA, (byte) 0xFB, 100});
    s.writeBytes(good);
    s.writeBytes(new byte[120]);
    feed(s.toByteArray(), 0);
    assertEquals(1, got.size());
    assertArrayEquals(good, got.get(0));
    assertEquals(1, drops.get(DropReason.BAD_CHECKSUM));
  }

  @Test
  void halfPacketIsAbandonedAfterTheTimeout() {
    byte[] p = packet(0x32, 1, 2, 3, 4, 5);
    receiver.feed(p, 0, 5, 0, collect);
    receiver.checkTimeout(50_000_000L, collect);
    assertEquals(0, drops.get(DropReason.TIMEOUT));
    receiver.checkTimeout(150_000_000L, collect);
    assertEquals(1, drops.get(DropReason.TIMEOUT));
    assertEquals(0, receiver.pendingBytes());
    byte[] next = packet(0x33, 9);
    feed(next, 200_000_000L);
    assertEquals(1, got.size());
    assertArrayEquals(next, got.get(0));
  }

  @Test
  void truncatedPacketFollowedLaterByAGoodOneIsTimedOutOnArrival() {
    byte[] p = packet(0x32, 1, 2, 3, 4, 5);
    receiver.feed(p, 0, 6, 0, collect);
    byte[] next = packet(0x33, 9);
    feed(next, 500_000_000L);
    assertEquals(1, got.size());
    assertArrayEquals(next, got.get(0));
    assertEquals(1, drops.get(DropReason.TIMEOUT));
  }

  @Test
  void randomGarbageNeverThrowsAndNeverGrowsTheBuffer() {
    Random rnd = new Random(42);
    for (int round = 0; round < 200; round++) {
      byte[] junk = new byte[rnd.nextInt(2000)];
      rnd.nextBytes(junk);
      if (rnd.nextBoolean()) {
        // headers make garbage much nastier
        for (int i = 0; i + 1 < junk.length; i += 1 + rnd.nextInt(20)) {
          junk[i] = (byte) 0xFA;
          junk[i + 1] = (byte) 0xFB;
        }
      }
      feed(junk, round * 1_000_000L);
      assertTrue(receiver.pendingBytes() <= ArRobotPacket.MAX_LENGTH);
    }
  }

  /**
   * Property: whatever garbage comes between valid packets (and however the stream is chunked),
   * every valid packet is delivered, in order.
   */
  @Test
  void everyValidPacketAfterGarbageIsDeliveredInOrder() {
    for (long seed = 1; seed <= 300; seed++) {
      Random rnd = new Random(seed);
      got.clear();
      receiver.reset();
      List<byte[]> sent = new ArrayList<>();
      ByteArrayOutputStream stream = new ByteArrayOutputStream();
      int packets = 1 + rnd.nextInt(20);
      for (int k = 0; k < packets; k++) {
        stream.writeBytes(garbage(rnd));
        byte[] p = randomPacket(rnd);
        sent.add(p);
        stream.writeBytes(p);
      }
      byte[] all = stream.toByteArray();
      int off = 0;
      while (off < all.length) {
        int n = Math.min(all.length - off, 1 + rnd.nextInt(64));
        receiver.feed(all, off, n, 0, collect);
        off += n;
      }
      // A lying header near the end may still be waiting for bytes that never come: once they
      // are overdue, the receiver looks inside it again.
      receiver.checkTimeout(1_000_000_000L, collect);
      List<byte[]> valid = new ArrayList<>();
      for (byte[] g : got) {
        if (sent.stream().anyMatch(s -> java.util.Arrays.equals(s, g))) {
          valid.add(g);
        }
      }
      assertEquals(sent.size(), valid.size(), "seed " + seed);
      for (int i = 0; i < sent.size(); i++) {
        assertArrayEquals(sent.get(i), valid.get(i), "seed " + seed + " packet " + i);
      }
    }
  }

  /** Random bytes with some fake headers (the interesting case: a header that lies). */
  private static byte[] garbage(Random rnd) {
    byte[] g = new byte[rnd.nextInt(300)];
    rnd.nextBytes(g);
    for (int i = 0; i + 2 < g.length; i += 1 + rnd.nextInt(40)) {
      g[i] = (byte) 0xFA;
      g[i + 1] = (byte) 0xFB;
      g[i + 2] = (byte) rnd.nextInt(256);
    }
    return g;
  }

  private static byte[] randomPacket(Random rnd) {
    ArRobotPacket p = new ArRobotPacket(rnd.nextInt(256));
    int n = rnd.nextInt(ArRobotPacket.MAX_DATA_LENGTH + 1);
    for (int i = 0; i < n; i++) {
      p.uByteToBuf(rnd.nextInt(256));
    }
    return p.finalizePacket().toByteArray();
  }
}
