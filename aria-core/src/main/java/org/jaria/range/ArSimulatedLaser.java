package org.jaria.range;

import org.jaria.geom.ArPose;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;

/**
 * The laser range finder of a simulator (MobileSim's or JAria's), read from the laser packets
 * (0x60, or 0x61 with reflectance) that come in the robot connection (ARIA's {@code
 * ArSimulatedLaser}). On connecting it sets the field of view and resolution and switches the laser
 * on; each completed sweep (a sweep spans several packets) fills the current buffer and is offered
 * as a {@link LaserScan} for actions such as {@code ArActionTriangleDriveTo}.
 */
public class ArSimulatedLaser extends ArRangeDevice implements LaserScanSource {

  private final double startDeg;
  private final double endDeg;
  private final double incrementDeg;
  private final Runnable onConnect = this::configure;
  private double[] sweep = new double[181];
  private int received;
  private volatile LaserScan lastScan;
  private long sweeps;

  /** A laser over −90..90° every 1°, 32 m maximum range (a SICK LMS200). */
  public ArSimulatedLaser() {
    this(-90, 90, 1, 32000);
  }

  /** A laser over {@code startDeg}..{@code endDeg} every {@code incrementDeg}. */
  public ArSimulatedLaser(double startDeg, double endDeg, double incrementDeg, double maxRange) {
    super("laser", maxRange, 361, 720);
    if (endDeg <= startDeg || incrementDeg <= 0) {
      throw new IllegalArgumentException(
          "laser field of view " + startDeg + ".." + endDeg + " by " + incrementDeg + " is empty");
    }
    this.startDeg = startDeg;
    this.endDeg = endDeg;
    this.incrementDeg = incrementDeg;
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    r.addPacketHandler(this::handle, ArListPos.LAST);
    r.addConnectCB(onConnect);
    if (r.isConnected()) {
      configure();
    }
  }

  /** Sends the field of view and resolution, then switches the simulated laser on. */
  private void configure() {
    ArRobot r = robot;
    r.comInt(ArCommands.SIM_LRF_SET_FOV_START, (int) Math.round(startDeg));
    r.comInt(ArCommands.SIM_LRF_SET_FOV_END, (int) Math.round(endDeg));
    r.comInt(ArCommands.SIM_LRF_SET_RES, (int) Math.round(incrementDeg * 100));
    r.comInt(ArCommands.SIM_LRF_ENABLE, 1);
  }

  /**
   * Reads a laser packet: 0x60 (the robot's odometry pose, then the readings' ranges) or 0x61,
   * which MobileSim and JAria's simulator send once ARIA's set-up asked for extended packets (no
   * pose; a reflectance byte and two reserved bytes after each range).
   */
  private boolean handle(ArRobotPacket p) {
    boolean extended = p.getID() == PacketIds.SIM_LASER_EXTENDED;
    if (p.getID() != PacketIds.SIM_LASER && !extended) {
      return false;
    }
    if (!extended) {
      p.bufToByte2(); // x, y, th of the robot's odometry: the robot's own pose is used instead
      p.bufToByte2();
      p.bufToByte2();
    }
    int total = p.bufToUByte2();
    int first = p.bufToUByte2();
    int n = p.bufToUByte();
    int perReading = extended ? 5 : 2;
    if (!p.isValid() || !p.isNextGood(perReading * n) || first + n > total || total > 4096) {
      robot.getDropCounters().drop(DropReason.MALFORMED, "laser packet");
      return true;
    }
    if (sweep.length != total) {
      sweep = new double[total];
      received = 0;
    }
    if (first == 0) {
      received = 0;
    }
    for (int i = 0; i < n; i++) {
      sweep[first + i] = p.bufToUByte2();
      if (extended) {
        p.skip(3); // reflectance, two reserved bytes
      }
    }
    received += n;
    if (first + n == total && received >= total) {
      completeSweep(total);
    }
    return true;
  }

  private void completeSweep(int total) {
    ArRobot r = robot;
    ArRobotParams params = r.getRobotParams();
    ArPose pose = r.getPose();
    double c = Math.cos(pose.getThRad());
    double s = Math.sin(pose.getThRad());
    ArPose sensor =
        new ArPose(
            pose.x() + c * params.getLaserX() - s * params.getLaserY(),
            pose.y() + s * params.getLaserX() + c * params.getLaserY(),
            pose.th() + params.getLaserTh());
    double[] ranges = new double[total];
    System.arraycopy(sweep, 0, ranges, 0, total);
    LaserScan scan = LaserScan.evenlySpaced(sensor, startDeg, incrementDeg, ranges, getMaxRange());
    long now = r.getClock().nanoTime();
    synchronized (this) {
      currentBuffer.clear();
      for (int i = 0; i < scan.getNumPoints(); i++) {
        currentBuffer.addReading(scan.getX(i), scan.getY(i), now);
        cumulativeBuffer.addReadingConditional(scan.getX(i), scan.getY(i), now, 50);
      }
      sweeps++;
    }
    lastScan = scan;
  }

  @Override
  public LaserScan getLaserScan() {
    return lastScan;
  }

  /** Complete sweeps received. */
  public synchronized long getSweepCount() {
    return sweeps;
  }
}
