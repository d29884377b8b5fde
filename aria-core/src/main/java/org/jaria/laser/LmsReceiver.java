package org.jaria.laser;

import java.util.function.Consumer;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;

/**
 * Finds LMS telegrams in a stream of bytes, however it is cut into reads. Bytes outside telegrams
 * (the laser's ACK/NAK bytes, line noise) are skipped and counted; a telegram whose CRC fails is
 * dropped and the search resumes one byte after its start, so a lost byte costs one telegram, not
 * the rest of the stream. Memory is bounded by the largest telegram.
 *
 * <p>Not thread-safe: one reader thread feeds it.
 */
public final class LmsReceiver {

  private final boolean fromLaser;
  private final DropCounters drops;
  private final byte[] buf = new byte[4 + LmsTelegram.MAX_LENGTH + 2];
  private int n;
  private int acks;
  private int naks;

  /**
   * A receiver.
   *
   * @param fromLaser true to accept telegrams from a laser (address 0x80–0x84, as a driver does),
   *     false to accept telegrams to one (address 0x00–0x04, as a laser or its emulator does)
   * @param drops where damaged telegrams and skipped bytes are counted
   */
  public LmsReceiver(boolean fromLaser, DropCounters drops) {
    this.fromLaser = fromLaser;
    this.drops = drops;
  }

  /** Feeds {@code len} bytes; each complete, intact telegram goes to {@code out}. */
  public void feed(byte[] b, int off, int len, Consumer<LmsTelegram> out) {
    for (int i = off; i < off + len; i++) {
      if (n == 0 && b[i] != LmsTelegram.STX) {
        countStray(b[i] & 0xff);
        continue;
      }
      buf[n++] = b[i];
      scan(out);
    }
  }

  private void countStray(int value) {
    if (value == LmsTelegram.ACK) {
      acks++;
    } else if (value == LmsTelegram.NAK) {
      naks++;
    } else {
      drops.skipped(1);
    }
  }

  /** Checks the bytes held so far; completes, keeps waiting, or resynchronises. */
  private void scan(Consumer<LmsTelegram> out) {
    while (n > 0) {
      if (buf[0] != LmsTelegram.STX) {
        countStray(buf[0] & 0xff);
        shift(1);
        continue;
      }
      if (n >= 2 && !addressOk(buf[1] & 0xff)) {
        drops.skipped(1);
        shift(1);
        continue;
      }
      if (n < 4) {
        return;
      }
      int len = (buf[2] & 0xff) | (buf[3] & 0xff) << 8;
      if (len < 1 || len > LmsTelegram.MAX_LENGTH) {
        drops.drop(DropReason.BAD_LENGTH, "LMS telegram length " + len);
        shift(1);
        continue;
      }
      int total = 4 + len + 2;
      if (n < total) {
        return;
      }
      int crc = (buf[total - 2] & 0xff) | (buf[total - 1] & 0xff) << 8;
      if (crc != LmsTelegram.crc(buf, 0, total - 2)) {
        drops.drop(DropReason.BAD_CHECKSUM, "LMS telegram");
        shift(1);
        continue;
      }
      byte[] data = new byte[len - 1];
      System.arraycopy(buf, 5, data, 0, data.length);
      LmsTelegram t = new LmsTelegram(buf[1] & 0xff, buf[4] & 0xff, data);
      shift(total);
      out.accept(t);
    }
  }

  private boolean addressOk(int a) {
    int base = fromLaser ? LmsTelegram.FROM_LASER : LmsTelegram.TO_LASER;
    return a >= base && a <= base + 4;
  }

  private void shift(int k) {
    System.arraycopy(buf, k, buf, 0, n - k);
    n -= k;
  }

  /** ACK bytes seen between telegrams. */
  public int getAckCount() {
    return acks;
  }

  /** NAK bytes seen between telegrams. */
  public int getNakCount() {
    return naks;
  }

  /** Forgets a half-received telegram (after a reconnect). */
  public void reset() {
    n = 0;
  }
}
