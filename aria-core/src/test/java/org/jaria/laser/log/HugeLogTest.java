package org.jaria.laser.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A 256 MB log read as a stream: the reader keeps one line, so the memory it needs does not depend
 * on the log's length. The log is generated on the fly (no such file on disk).
 */
@Tag("slow")
class HugeLogTest {

  /** A header, then one scan block repeated until {@code size} bytes, then the end marker. */
  static final class RepeatingLog extends InputStream {
    private final byte[] header;
    private final byte[] block;
    private final byte[] end = "# End of log\n".getBytes(StandardCharsets.ISO_8859_1);
    private final long size;
    private long pos;
    private long blocks;

    RepeatingLog(String header, String block, long size) {
      this.header = header.getBytes(StandardCharsets.ISO_8859_1);
      this.block = block.getBytes(StandardCharsets.ISO_8859_1);
      this.size = size;
    }

    long blocks() {
      return blocks;
    }

    @Override
    public int read() {
      byte[] one = new byte[1];
      return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
    }

    @Override
    public int read(byte[] b, int off, int len) {
      if (pos < header.length) {
        int n = (int) Math.min(len, header.length - pos);
        System.arraycopy(header, (int) pos, b, off, n);
        pos += n;
        return n;
      }
      long body = pos - header.length;
      long bodySize = blocks * block.length;
      if (body < bodySize || (bodySize < size && body == bodySize)) {
        if (body == bodySize) {
          blocks++;
          bodySize += block.length;
        }
        int at = (int) (body % block.length);
        int n = Math.min(len, block.length - at);
        System.arraycopy(block, at, b, off, n);
        pos += n;
        return n;
      }
      long e = body - bodySize;
      if (e >= end.length) {
        return -1;
      }
      int n = (int) Math.min(len, end.length - e);
      System.arraycopy(end, (int) e, b, off, n);
      pos += n;
      return n;
    }
  }

  @Test
  void aLongLogStreamsThroughInBoundedMemory() throws IOException {
    StringBuilder readings = new StringBuilder();
    for (int i = 0; i < 181; i++) {
      readings.append(1000 + i).append(' ').append(-2000 + 7 * i).append("  ");
    }
    String block = ScanLogReaderTest.scan(0, 1.5, 300, readings.toString());
    long size = 1L << 28;
    RepeatingLog in = new RepeatingLog(ScanLogReaderTest.HEADER, block, size);
    Runtime rt = Runtime.getRuntime();
    long scans = 0;
    long readingsSeen = 0;
    long maxUsed = 0;
    try (ScanLogReader r = ScanLogReader.of(in, "generated.2d")) {
      for (ScanLogEntry e = r.next(); e != null; e = r.next()) {
        readingsSeen += ((LoggedScan) e).size();
        if (++scans % 50_000 == 0) {
          // Live data only: without a collection first, the reading would count whatever garbage
          // the collector has not yet reclaimed (hundreds of MB with a large young generation, and
          // more in a JVM that ran other test classes before this one).
          System.gc();
          maxUsed = Math.max(maxUsed, rt.totalMemory() - rt.freeMemory());
        }
      }
      assertEquals(in.blocks(), r.stats().scans());
      assertTrue(r.stats().endMarker());
    }
    assertEquals(in.blocks(), scans);
    assertEquals(181 * scans, readingsSeen);
    assertTrue(scans * block.length() >= size, "the whole log was read: " + scans);
    // Nothing accumulates: the heap in use stays far below the 256 MB read.
    assertTrue(maxUsed > 0, "the heap was measured");
    assertTrue(maxUsed < 64L << 20, "heap in use " + (maxUsed >> 20) + " MB");
  }
}
