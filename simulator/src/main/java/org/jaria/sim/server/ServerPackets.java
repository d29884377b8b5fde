package org.jaria.sim.server;

import org.jaria.geom.ArMath;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.ArConfigPacket.Field;
import org.jaria.protocol.packets.EncoderPacket;
import org.jaria.protocol.packets.GripperPacket;
import org.jaria.protocol.packets.IoPacket;
import org.jaria.protocol.packets.JoystickPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.SimStatPacket;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.protocol.packets.Tcm2Packet;
import org.jaria.sim.OdometryError;
import org.jaria.sim.robot.GyroModel;
import org.jaria.sim.robot.LaserModel;
import org.jaria.sim.robot.MotionController;
import org.jaria.sim.robot.Odometry;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.robot.RobotIo;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.robot.SimProfile;
import org.jaria.sim.robot.SonarModel;

/**
 * Builds the packets a simulated robot sends, in robot units (the model's conversion factors), the
 * way ARCOS and MobileSim lay them out. Every method fills a caller-owned packet.
 */
public final class ServerPackets {

  /**
   * Robot name in the SYNC2 reply and CONFIGpac: MobileSim's, because ARIA 2.9.1 treats a robot as
   * a simulator (and asks it for the laser instead of opening a serial port) only by this name;
   * AriaCoda also goes by {@link #SERIAL}. The simulator's own name is in SIMINFO ({@link
   * #SIM_NAME}).
   */
  public static final String ROBOT_NAME = "MobileSim";

  /** Serial number in CONFIGpac; clients recognise a simulator by it. */
  public static final String SERIAL = "SIM";

  /**
   * Firmware version in CONFIGpac of the {@code pioneer} profile ("S" marks a simulator, like
   * MobileSim's "S.0", which the {@code mobilesim} profile sends).
   */
  public static final String FIRMWARE_VERSION = "S.1";

  /** Simulator name in SIMINFO. */
  public static final String SIM_NAME = "JAriaSim";

  /** Simulator version in SIMINFO. */
  public static final String SIM_VERSION = "0.1";

  /** Optional SIP fields sent: GRIP_STATE through FAULT_FLAGS (the thesis's table 4.1). */
  public static final int SIP_OPTIONALS = 9;

  /**
   * Optional SIP fields MobileSim sends: up to the state of charge (lateral velocity, temperature,
   * state of charge after the fault flags).
   */
  public static final int MOBILESIM_SIP_OPTIONALS = 12;

  /** The temperature byte MobileSim sends for "no temperature sensor". */
  public static final int MOBILESIM_NO_TEMPERATURE = -127;

  /** Most laser readings per laser packet (as MobileSim). */
  public static final int LASER_READINGS_PER_PACKET = 32;

  private ServerPackets() {}

  /** The SYNC2 reply: ID 2, then name, type and subtype, each NUL-terminated. */
  public static ArRobotPacket sync2(ArRobotPacket p, RobotModel m) {
    p.empty().setID(2);
    p.strToBuf(ROBOT_NAME).strToBuf(m.getRobotClass()).strToBuf(m.getSubtype());
    return p.finalizePacket();
  }

  /** A SYNC0 or SYNC1 echo. */
  public static ArRobotPacket syncEcho(ArRobotPacket p, int id) {
    return p.empty().setID(id).finalizePacket();
  }

  /**
   * The standard SIP; takes the pending sonar readings out of the sonar queue. In the {@code
   * mobilesim} profile it is laid out as MobileSim's: always ID 0x32, stall bits without bumpers,
   * CONTROL 0, and the tail up to the state of charge (lateral velocity 0, temperature -127 for "no
   * sensor", state of charge 0).
   */
  public static ArRobotPacket sip(ArRobotPacket p, StandardSip sip, RobotBody b) {
    RobotModel m = b.model();
    Odometry o = b.odometry();
    MotionController mc = b.motion();
    RobotIo io = b.io();
    boolean mobileSim = b.profile() == SimProfile.MOBILESIM;
    double v = mc.getVel();
    double w = mc.getRotVel();
    double half = Math.toRadians(w) * m.getTrackWidth() / 2;
    sip.setMoving(!mobileSim && (Math.abs(v) >= 0.5 || Math.abs(w) >= 0.05));
    // THPOS counts angle units round and round (Odometry.getThUnits says why not from the heading).
    int thUnits = o.getThUnits(m.getAngleConvFactor());
    sip.setPos(
        (int) Math.round(o.getX() / m.getDistConvFactor()),
        (int) Math.round(o.getY() / m.getDistConvFactor()),
        thUnits);
    sip.setWheelVels(
        (int) Math.round((v - half) / m.getVelConvFactor()),
        (int) Math.round((v + half) / m.getVelConvFactor()));
    sip.setBattery(Math.min(255, io.getBattery()));
    int stall = b.takeLatchedStallBits();
    // MobileSim simulates no bumpers: a collision shows as both motors stalled, nothing else
    sip.setStallAndBumpers(
        mobileSim ? stall & (RobotBody.STALL_LEFT | RobotBody.STALL_RIGHT) : stall);
    // The heading setpoint travels in angle units like THPOS (ARIA reads it that way), counted
    // from THPOS so that the difference ARIA takes is the angle whatever the wrap.
    double toControl = ArMath.subAngle(mc.getControlHeading(o.getTh()), o.getTh());
    sip.setControl(
        mobileSim
            ? 0
            : thUnits + (int) Math.round(Math.toRadians(toControl) / m.getAngleConvFactor()));
    int flags = mc.areMotorsEnabled() ? 1 : 0;
    flags |= b.sonar().getEnabledArrays() << 1;
    sip.setFlags(flags);
    sip.setCompass(io.getCompassMode() > 0 ? compassByte(b.trueTh()) : 0);
    sip.clearSonar();
    SonarModel s = b.sonar();
    if (s.allEachSip()) {
      // MobileSim: the last reading of every transducer, in every SIP
      for (int i = 0; i < s.size(); i++) {
        if (s.measuredThisSession(i)) {
          sip.addSonar(i, (int) Math.round(s.reportedRange(i) / m.getRangeConvFactor()));
        }
      }
    } else {
      for (int k = 0; k < s.pendingCount(); k++) {
        sip.addSonar(
            s.pendingNumber(k), (int) Math.round(s.pendingRange(k) / m.getRangeConvFactor()));
      }
    }
    s.clearPending();
    int grip = b.gripper() != null ? b.gripper().state() : 0;
    sip.setIo(grip, io.getAnPort(), io.selectedAnalogByte(), digIn(b), io.getDigOut());
    sip.setPower(io.getBattery(), 0, (int) Math.round(w * 10), 0);
    if (mobileSim) {
      sip.setExtended(0, MOBILESIM_NO_TEMPERATURE, 0, 0, 0);
      sip.setOptionalCount(MOBILESIM_SIP_OPTIONALS);
    } else {
      sip.setOptionalCount(SIP_OPTIONALS);
    }
    return sip.encode(p);
  }

  /**
   * DIGIN: the user inputs, with a Pioneer gripper's switches on bits 0–5 where it is wired (ARIA
   * reads a user-I/O gripper there).
   */
  static int digIn(RobotBody b) {
    int in = b.io().getDigIn();
    return b.gripper() == null ? in : (in & 0xC0) | (b.gripper().state() & 0x3F);
  }

  /**
   * The compass byte (2° per unit) for a true heading: the heading counter-clockwise from the map's
   * +x axis, 0..358°, so it compares directly with the robot's heading.
   */
  static int compassByte(double trueThDeg) {
    double h = trueThDeg < 0 ? trueThDeg + 360 : trueThDeg;
    return ((int) Math.round(h / 2)) % 180;
  }

  /**
   * CONFIGpac from the model and the session's current settings (in the {@code mobilesim} profile,
   * MobileSim's values: see {@link MobileSimConfig}).
   */
  public static ArRobotPacket config(
      ArRobotPacket p, RobotBody b, int sipCycleMs, int watchdogMs, int gyroCw, int gyroCcw) {
    if (b.profile() == SimProfile.MOBILESIM) {
      return MobileSimConfig.config(p, b, sipCycleMs, watchdogMs);
    }
    RobotModel m = b.model();
    MotionController mc = b.motion();
    ArConfigPacket c = new ArConfigPacket();
    c.set(Field.TYPE, m.getRobotClass());
    c.set(Field.SUBTYPE, m.getSubtype());
    c.set(Field.SERIAL_NUMBER, SERIAL);
    c.set(Field.LEGACY, 0);
    c.set(Field.ROT_VEL_TOP, round(m.getRotVelTop()));
    c.set(Field.TRANS_VEL_TOP, round(m.getTransVelTop()));
    c.set(Field.ROT_ACCEL_TOP, round(m.getRotAccTop()));
    c.set(Field.TRANS_ACCEL_TOP, round(m.getTransAccTop()));
    c.set(Field.PWM_MAX, 500);
    c.set(Field.NAME, ROBOT_NAME);
    c.set(Field.SIP_CYCLE_TIME, Math.min(255, sipCycleMs));
    c.set(Field.HOST_BAUD, 0);
    c.set(Field.AUX1_BAUD, 0);
    c.set(Field.HAS_GRIPPER, b.gripper() != null ? 1 : 0);
    c.set(Field.FRONT_SONAR, m.getNumSonar() > 0 ? 1 : 0);
    c.set(Field.REAR_SONAR, m.getNumSonar() > 8 ? 1 : 0);
    c.set(Field.LOW_BATTERY, 110);
    c.set(Field.REV_COUNT, b.odometry().getRevCount());
    c.set(Field.WATCHDOG, Math.min(65535, watchdogMs));
    c.set(Field.NORMAL_MPACS, 0);
    c.set(Field.STALL_VAL, 0);
    c.set(Field.STALL_COUNT, 0);
    c.set(Field.JOY_VEL, 0);
    c.set(Field.JOY_ROT_VEL, 0);
    c.set(Field.ROT_VEL_MAX, round(mc.getRotVelMax()));
    c.set(Field.TRANS_VEL_MAX, round(mc.getTransVelMax()));
    c.set(Field.ROT_ACCEL, round(mc.getRotAccel()));
    c.set(Field.ROT_DECEL, round(mc.getRotDecel()));
    c.set(Field.TRANS_ACCEL, round(mc.getTransAccel()));
    c.set(Field.TRANS_DECEL, round(mc.getTransDecel()));
    c.set(Field.FRONT_BUMPS, m.getNumFrontBumpers());
    c.set(Field.REAR_BUMPS, m.getNumRearBumpers());
    c.set(Field.HAS_CHARGER, 0);
    c.set(Field.SONAR_CYCLE, b.sonar().getCycle());
    c.set(Field.RESET_BAUD, 0);
    c.set(Field.HAS_GYRO, b.gyro() != null ? 1 : 0);
    c.set(Field.DRIFT_FACTOR, b.odometry().getDriftFactor());
    c.set(Field.AUX2_BAUD, 0);
    c.set(Field.AUX3_BAUD, 0);
    c.set(Field.TICKS_MM, b.odometry().getTicksMm());
    c.set(Field.SHUTDOWN_VOLTS, 105);
    c.set(Field.FIRMWARE_VERSION, FIRMWARE_VERSION);
    c.set(Field.GYRO_CW, gyroCw);
    c.set(Field.GYRO_CCW, gyroCcw);
    c.set(Field.CHARGE_THRESHOLD, 0);
    return c.encode(p);
  }

  private static int round(double v) {
    return (int) Math.max(0, Math.min(65535, Math.round(v)));
  }

  /** ENCODERpac with the raw encoder counts. */
  public static ArRobotPacket encoder(ArRobotPacket p, RobotBody b) {
    return new EncoderPacket(b.odometry().getLeftEncoder(), b.odometry().getRightEncoder())
        .encode(p);
  }

  /**
   * IOpac: DIGIN, front bumpers, rear bumpers, IRs (bumpers and IRs read active-low, as the thesis
   * describes the raw inputs), DIGOUT, then the analog ports and the battery analog.
   */
  public static ArRobotPacket io(ArRobotPacket p, RobotBody b) {
    RobotIo io = b.io();
    int stall = b.getStallBits();
    int front = ~(stall >> 8) & 0xFE;
    int rear = ~stall & 0xFE;
    int[] an = new int[RobotIo.ANALOG_PORTS + 1];
    for (int i = 0; i < RobotIo.ANALOG_PORTS; i++) {
      an[i] = io.getAnalog(i);
    }
    an[RobotIo.ANALOG_PORTS] = io.batteryAnalog();
    return new IoPacket(new int[] {digIn(b), front, rear, 0xFF}, new int[] {io.getDigOut()}, an)
        .encode(p);
  }

  /** GRIPPERpac. */
  public static ArRobotPacket gripper(ArRobotPacket p, RobotBody b) {
    int state = b.gripper() != null ? b.gripper().state() : 0;
    int grasp = b.gripper() != null ? b.gripper().graspTime() : 0;
    return new GripperPacket(b.gripper() != null ? 1 : 0, state, grasp).encode(p);
  }

  /** JOYSTICKpac of an untouched joystick (buttons up, axes centred). */
  public static ArRobotPacket joystick(ArRobotPacket p) {
    return new JoystickPacket(0, 0, 512, 512, 0).encode(p);
  }

  /** GYROpac with the samples taken since the last one (clears them). */
  public static ArRobotPacket gyro(ArRobotPacket p, GyroModel g) {
    int n = Math.min(g.pendingCount(), 66);
    p.empty().setID(PacketIds.GYRO).uByteToBuf(n);
    for (int k = 0; k < n; k++) {
      p.uByte2ToBuf(g.pendingRate(k)).uByteToBuf(g.pendingTemperature(k));
    }
    g.clearPending();
    return p.finalizePacket();
  }

  /**
   * TCM2pac as ARIA's {@code ArTCMCompassRobot} reads it: heading (0.1°), pitch, roll, X, Y, Z
   * field, temperature, error (int16 each), H and V calibration scores (uint8), M score (int16).
   * The heading comes first on the wire (the byte count of 23 in the thesis's table includes it).
   */
  public static ArRobotPacket tcm2(ArRobotPacket p, double trueThDeg) {
    double h = trueThDeg < 0 ? trueThDeg + 360 : trueThDeg;
    double r = Math.toRadians(trueThDeg);
    return new Tcm2Packet(
            (int) Math.round(h * 10),
            0,
            0,
            (int) Math.round(Math.cos(r) * 2000),
            (int) Math.round(-Math.sin(r) * 2000),
            -4000,
            220,
            0,
            9,
            9,
            100)
        .encode(p);
  }

  /** SIMSTAT with the robot's true pose. */
  public static ArRobotPacket simStat(ArRobotPacket p, RobotBody b, SessionHost host) {
    OdometryError e = b.odometry().getError();
    long flags =
        (host.haveMap() ? SimStatPacket.FLAG_HAVE_MAP : 0)
            | (e.mode() != OdometryError.Mode.NONE ? SimStatPacket.FLAG_ODOMETRY_ERROR : 0);
    return new SimStatPacket(
            flags,
            host.simIntervalMillis(),
            host.realIntervalMillis(),
            host.lastIntervalMillis(),
            (int) Math.round(b.trueX()),
            (int) Math.round(b.trueY()),
            0,
            (int) Math.round(b.trueTh()),
            0,
            0,
            0,
            -1,
            (int) Math.round(e.transPerMetre() * 1e6),
            (int) Math.round(e.transPerMetre() * 1e6),
            (int) Math.round(e.rotPerRadian() * 1e6))
        .encode(p);
  }

  /** SIMINFO: simulator name and version, flags, and the robot's devices. */
  public static ArRobotPacket simInfo(ArRobotPacket p, RobotBody b) {
    p.empty().setID(PacketIds.SIMINFO).strToBuf(SIM_NAME).strToBuf(SIM_VERSION);
    p.uByte4ToBuf(0);
    int devices = 1 + (b.laser() != null ? 1 : 0);
    p.uByte4ToBuf(devices);
    p.strToBuf("sonar").strToBuf("sonar").uByteToBuf(1).uByte4ToBuf(1);
    if (b.laser() != null) {
      p.strToBuf("laser_1").strToBuf("laser").uByteToBuf(1).uByte4ToBuf(1);
    }
    return p.finalizePacket();
  }

  /** SIM_MAP_CHANGED (0x66): user flag, loaded status (1 new map, 0 unchanged, −1 failed), file. */
  public static ArRobotPacket mapChanged(ArRobotPacket p, boolean user, int status, String file) {
    p.empty().setID(PacketIds.SIM_MAP_CHANGED).uByteToBuf(user ? 1 : 0).byteToBuf(status);
    String name = file.length() > 190 ? file.substring(file.length() - 190) : file;
    return p.strToBuf(name).finalizePacket();
  }

  /**
   * One laser packet of the last scan, readings {@code first} .. first+31, laid out as MobileSim
   * sends them and ARIA's {@code ArSimulatedLaser} reads them: 0x60 starts with the odometry pose
   * (mm, mm, degrees as int16); then the scan's reading count, the index of this packet's first
   * reading and the number of readings in it; then per reading the range (mm, uint16) and, in 0x61
   * only, a reflectance byte and two reserved bytes; 0x61 ends with the laser's index and a flags
   * byte. Reflectance is 0 for everything the simulated laser sees (MobileSim's value for an
   * ordinary wall; JAria's maps have no reflectors).
   */
  public static ArRobotPacket laser(
      ArRobotPacket p, LaserModel l, RobotBody b, int first, boolean extended) {
    int total = l.lastCount();
    int n = Math.min(LASER_READINGS_PER_PACKET, total - first);
    p.empty().setID(extended ? PacketIds.SIM_LASER_EXTENDED : PacketIds.SIM_LASER);
    if (!extended) {
      Odometry o = b.odometry();
      p.byte2ToBuf((int) Math.round(o.getX()))
          .byte2ToBuf((int) Math.round(o.getY()))
          .byte2ToBuf((int) Math.round(ArMath.fixAngle(o.getTh())));
    }
    p.uByte2ToBuf(total).uByte2ToBuf(first).uByteToBuf(n);
    for (int k = first; k < first + n; k++) {
      p.uByte2ToBuf(Math.min(65535, l.range(k)));
      if (extended) {
        p.uByteToBuf(0).uByteToBuf(0).uByteToBuf(0);
      }
    }
    if (extended) {
      p.uByteToBuf(0).uByteToBuf(0);
    }
    return p.finalizePacket();
  }
}
