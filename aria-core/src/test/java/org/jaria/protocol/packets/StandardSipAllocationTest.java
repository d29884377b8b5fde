package org.jaria.protocol.packets;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.DropCounters;
import org.junit.jupiter.api.Test;

/** The SIP hot path (receive + decode) must not allocate per packet. */
class StandardSipAllocationTest {

  @Test
  void receivingAndDecodingSipsAllocatesNothingPerPacket() {
    com.sun.management.ThreadMXBean mx =
        (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    StandardSip s = new StandardSip().setMoving(true).setPos(100, 200, 300);
    for (int i = 0; i < 16; i++) {
      s.addSonar(i, 1000 + i);
    }
    s.setOptionalCount(9);
    byte[] frame = s.encode(new ArRobotPacket()).toByteArray();
    StandardSip target = new StandardSip();
    ArRobotPacketReceiver receiver = new ArRobotPacketReceiver(new DropCounters("alloc"));
    long[] decoded = new long[1];
    ArRobotPacketReceiver.Listener l =
        p -> {
          if (target.decode(p)) {
            decoded[0]++;
          }
        };
    for (int i = 0; i < 20_000; i++) {
      receiver.feed(frame, 0, frame.length, i, l); // warm up, let the JIT settle
    }
    long tid = Thread.currentThread().getId();
    long before = mx.getThreadAllocatedBytes(tid);
    int n = 100_000;
    for (int i = 0; i < n; i++) {
      receiver.feed(frame, 0, frame.length, i, l);
    }
    long allocated = mx.getThreadAllocatedBytes(tid) - before;
    assertTrue(decoded[0] >= n);
    // A single 16-byte object per packet would be 1.6 MB; allow a little noise for the VM itself.
    assertTrue(allocated < 64 * 1024, "allocated " + allocated + " bytes for " + n + " SIPs");
  }
}
