package org.jaria.classroom.link;

import java.io.IOException;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.DropCounters;

/**
 * The robot channel of a student's link, seen from the grading world: the bytes the student's
 * ArRobot wrote are cut into ARCOS packets, and only the packets of commands a real Pioneer accepts
 * ({@link RobotCommands#accepted}) reach the simulated robot. Everything else (simulator control,
 * unknown numbers, damaged packets, bytes between packets) is counted in the {@link LinkAudit} and
 * goes no further. A packet split across two ticks is held until its end arrives (or is dropped
 * after ARIA's receive timeout of virtual time).
 *
 * <p>Used by the grading thread only.
 */
final class RobotCommandFilter {

  private final LinkAudit audit;
  private final ArRobotPacketReceiver receiver;
  private long countedDrops;
  private long countedGarbage;
  private ArDeviceConnection sink;
  private IOException failed;

  RobotCommandFilter(LinkAudit audit, String robotName) {
    this.audit = audit;
    this.receiver = new ArRobotPacketReceiver(new DropCounters(robotName + " (student link)"));
  }

  /** Carries the accepted packets among {@code len} bytes of {@code b}, received at {@code now}. */
  void feed(byte[] b, int len, long nowNanos, ArDeviceConnection to) throws IOException {
    sink = to;
    failed = null;
    if (len > 0) {
      receiver.feed(b, 0, len, nowNanos, this::packet);
    } else {
      receiver.checkTimeout(nowNanos, this::packet);
    }
    DropCounters d = receiver.drops();
    long drops = d.total();
    for (; countedDrops < drops; countedDrops++) {
      audit.dropped("damaged packets");
    }
    long garbage = d.skippedBytes();
    if (garbage > countedGarbage) {
      audit.garbage(garbage - countedGarbage);
      countedGarbage = garbage;
    }
    if (failed != null) {
      throw failed;
    }
  }

  private void packet(ArRobotPacket p) {
    if (!audit.carries(p.getID())) {
      audit.dropped(RobotCommands.name(p.getID()));
      return;
    }
    if (failed == null && sink.getStatus() == ArDeviceConnection.Status.OPEN) {
      try {
        sink.write(p.getBuf(), 0, p.getLength());
      } catch (IOException e) {
        failed = e;
      }
    }
  }
}
