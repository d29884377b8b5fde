package org.jaria.connection;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import org.jaria.clock.VirtualClock;
import org.junit.jupiter.api.Test;

class PipeConnectionTest {

  private final VirtualClock clock = new VirtualClock();
  private final PipeConnection.Pair pair = PipeConnection.pair(clock);
  private final PipeConnection a = pair.a();
  private final PipeConnection b = pair.b();

  PipeConnectionTest() throws IOException {
    a.open();
    b.open();
  }

  @Test
  void bytesGoBothWays() throws IOException {
    a.write(new byte[] {1, 2, 3}, 0, 3);
    b.write(new byte[] {9}, 0, 1);
    byte[] buf = new byte[10];
    assertEquals(3, b.read(buf, 0, 10, 0));
    assertArrayEquals(new byte[] {1, 2, 3}, java.util.Arrays.copyOf(buf, 3));
    assertEquals(1, a.read(buf, 0, 10, 0));
    assertEquals(9, buf[0]);
    assertEquals(0, a.read(buf, 0, 10, 0));
  }

  @Test
  void largeWritesGrowTheBufferAndWrapCorrectly() throws IOException {
    byte[] big = new byte[100_000];
    for (int i = 0; i < big.length; i++) {
      big[i] = (byte) (i * 31);
    }
    byte[] got = new byte[big.length];
    int read = 0;
    for (int round = 0; round < 3; round++) {
      a.write(big, 0, 5000);
      read = 0;
      while (read < 3000) {
        read += b.read(got, read, 3000 - read, 0);
      }
    }
    a.write(big, 0, big.length);
    int total = 0;
    byte[] sink = new byte[200_000];
    int n;
    while ((n = b.read(sink, total, sink.length - total, 0)) > 0) {
      total += n;
    }
    assertEquals(3 * 2000 + big.length, total);
    assertEquals(big[big.length - 1], sink[total - 1]);
  }

  @Test
  void readTimeoutPassesOnlyWithVirtualTime() throws Exception {
    int[] result = {-2};
    Thread reader =
        new Thread(
            () -> {
              try {
                result[0] = b.read(new byte[4], 0, 4, 500);
              } catch (IOException e) {
                result[0] = -3;
              }
            },
            "pipe-reader");
    reader.start();
    assertTrue(clock.awaitWaiters(1, Duration.ofSeconds(10)), "the reader waits on the clock");
    clock.advanceMillis(499);
    assertTrue(reader.isAlive());
    clock.advanceMillis(1);
    reader.join(10_000);
    assertFalse(reader.isAlive());
    assertEquals(0, result[0]);
  }

  @Test
  void closingOneEndGivesEndOfStreamAtTheOther() throws IOException {
    a.write(new byte[] {5}, 0, 1);
    a.close();
    byte[] buf = new byte[4];
    assertEquals(1, b.read(buf, 0, 4, 0));
    assertEquals(-1, b.read(buf, 0, 4, 100));
    assertEquals(ArDeviceConnection.Status.CLOSED_ERROR, b.getStatus());
    assertEquals(ArDeviceConnection.Status.CLOSED_NORMALLY, a.getStatus());
    assertThrows(IOException.class, () -> a.read(buf, 0, 4, 0));
  }

  @Test
  void brokenConnectionFailsWritesOnTheOtherEnd() {
    a.breakConnection();
    assertEquals(ArDeviceConnection.Status.CLOSED_ERROR, a.getStatus());
    assertThrows(IOException.class, () -> b.write(new byte[1], 0, 1));
  }
}
