package org.jaria.compass;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.DoubleConsumer;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.Tcm2Packet;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;

/**
 * A TCM2 compass connected to the robot's microcontroller (ARIA's {@code ArTCM2} as {@code
 * ArTCMCompassRobot}): its commands are TCM2 command modes, its readings arrive as TCM2pacs
 * (heading, pitch, roll, magnetic field, temperature, error bits, calibration scores).
 */
public class ArTCM2 {

  /** TCM2 modes: off, heading in the SIP, one TCM2pac, continuous TCM2pacs, ... */
  static final int OFF = 0;

  static final int JUST_COMPASS = 1;
  static final int ONE_PACKET = 2;
  static final int CONTINUOUS = 3;
  static final int USER_CALIBRATION = 4;
  static final int AUTO_CALIBRATION = 5;
  static final int STOP_CALIBRATION = 6;
  static final int SOFT_RESET = 7;

  private final ArRobot robot;
  private final List<DoubleConsumer> headingCallbacks = new CopyOnWriteArrayList<>();
  private final AtomicLong packets = new AtomicLong();
  private volatile Tcm2Packet last;

  /** A compass on {@code robot}. Ask for readings with {@link #commandContinuousPackets()}. */
  public ArTCM2(ArRobot robot) {
    this.robot = robot;
    robot.addPacketHandler(this::handle, ArListPos.FIRST);
  }

  private boolean handle(ArRobotPacket p) {
    if (p.getID() != PacketIds.TCM2) {
      return false;
    }
    Tcm2Packet t = Tcm2Packet.decode(p);
    if (t != null) {
      last = t;
      packets.incrementAndGet();
      double h = getHeading();
      headingCallbacks.forEach(cb -> cb.accept(h));
    }
    return true;
  }

  private boolean mode(int m) {
    return robot.comInt(ArCommands.TCM2, m);
  }

  /** Switches the compass off. */
  public boolean commandOff() {
    return mode(OFF);
  }

  /** Heading only, in the SIP. */
  public boolean commandJustCompass() {
    return mode(JUST_COMPASS);
  }

  /** Asks for one TCM2pac. */
  public boolean commandOnePacket() {
    return mode(ONE_PACKET);
  }

  /** Asks for a TCM2pac every cycle. */
  public boolean commandContinuousPackets() {
    return mode(CONTINUOUS);
  }

  /** Starts user calibration (turn the robot slowly through two full circles). */
  public boolean commandUserCalibration() {
    return mode(USER_CALIBRATION);
  }

  /** Starts automatic calibration. */
  public boolean commandAutoCalibration() {
    return mode(AUTO_CALIBRATION);
  }

  /** Stops a calibration and sends one TCM2pac with its scores. */
  public boolean commandStopCalibration() {
    return mode(STOP_CALIBRATION);
  }

  /** Resets the compass module. */
  public boolean commandSoftReset() {
    return mode(SOFT_RESET);
  }

  /** Adds a callback given each new heading (degrees), on the robot's cycle thread. */
  public void addHeadingDataCallback(DoubleConsumer cb) {
    headingCallbacks.add(cb);
  }

  private Tcm2Packet lastOrZero() {
    Tcm2Packet t = last;
    return t == null ? new Tcm2Packet(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0) : t;
  }

  /** Heading, degrees 0..360 (0 before the first packet). */
  public double getHeading() {
    return lastOrZero().heading() / 10.0;
  }

  /** Pitch, degrees. */
  public double getPitch() {
    return lastOrZero().pitch() / 10.0;
  }

  /** Roll, degrees. */
  public double getRoll() {
    return lastOrZero().roll() / 10.0;
  }

  /** Magnetic field along X. */
  public double getXMagnetic() {
    return lastOrZero().magX();
  }

  /** Magnetic field along Y. */
  public double getYMagnetic() {
    return lastOrZero().magY();
  }

  /** Magnetic field along Z. */
  public double getZMagnetic() {
    return lastOrZero().magZ();
  }

  /** Temperature, as the module reports it. */
  public double getTemperature() {
    return lastOrZero().temperature();
  }

  /** The module's error bits. */
  public int getError() {
    return lastOrZero().error();
  }

  /** Horizontal calibration score. */
  public double getCalibrationH() {
    return lastOrZero().calH();
  }

  /** Vertical calibration score. */
  public double getCalibrationV() {
    return lastOrZero().calV();
  }

  /** Magnetic calibration score. */
  public double getCalibrationM() {
    return lastOrZero().calM();
  }

  /** TCM2pacs received. */
  public long getPacketCount() {
    return packets.get();
  }

  /** Whether any TCM2pac has arrived. */
  public boolean haveData() {
    return last != null;
  }
}
