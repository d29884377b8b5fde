package org.jaria.range;

import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.robot.ArRobot;

/**
 * Infrared proximity sensors as a range device (ARIA's {@code ArIRs}), for robots whose parameter
 * file lists {@code IRUnit}s (PeopleBot table and cliff sensors, AmigoBot). A triggered IR puts a
 * reading at its position on the robot. IR bits are active-low: 0 means something is there. They
 * are read from the fourth IOpac digital-input byte when the parameters say the robot has the new
 * table-sensing IRs and IOpacs arrive, else from the SIP's DIGIN byte.
 */
public class ArIRs extends ArRangeDevice {

  private final long keepNanos;

  /** IRs with ARIA's defaults: readings kept 15 s. */
  public ArIRs() {
    this("irs", 15);
  }

  /** IRs whose readings are kept {@code keepSeconds}. */
  public ArIRs(String name, int keepSeconds) {
    super(name, 5000, 8, 8);
    this.keepNanos = TimeUnit.SECONDS.toNanos(keepSeconds);
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    r.addSensorInterpTask(getName(), 48, this::processReadings);
  }

  /** Adds a reading for each triggered IR; drops old readings. Runs each cycle. */
  public void processReadings() {
    ArRobot r = robot;
    if (r == null || r.getStatus().counter() < 0) {
      return;
    }
    ArRobotParams p = r.getRobotParams();
    long now = r.getClock().nanoTime();
    int bits = p.haveNewTableSensingIR() && r.getIODigInSize() > 3 ? r.getIODigIn(3) : r.getDigIn();
    ArTransform toGlobal = r.getToGlobalTransform();
    synchronized (this) {
      currentBuffer.removeIf((x, y, t) -> now - t > keepNanos);
      cumulativeBuffer.removeIf((x, y, t) -> now - t > keepNanos);
      for (int i = 0; i < p.getNumIR() && i < 8; i++) {
        if ((bits & (1 << i)) == 0) {
          double x = toGlobal.transformX(p.getIRX(i), p.getIRY(i));
          double y = toGlobal.transformY(p.getIRX(i), p.getIRY(i));
          currentBuffer.addReadingConditional(x, y, now, 10);
          cumulativeBuffer.addReadingConditional(x, y, now, 10);
        }
      }
    }
  }
}
