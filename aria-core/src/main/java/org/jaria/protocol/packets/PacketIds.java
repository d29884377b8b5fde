package org.jaria.protocol.packets;

/** IDs of the packets a robot (or simulator) sends to its client. */
public final class PacketIds {

  /** Standard SIP, motors stopped. */
  public static final int SIP_STOPPED = 0x32;

  /** Standard SIP, robot moving. */
  public static final int SIP_MOVING = 0x33;

  /** CONFIGpac, the answer to CONFIG. */
  public static final int CONFIG = 0x20;

  /** ENCODERpac: raw encoder counts. */
  public static final int ENCODER = 0x90;

  /** GYROpac: rate gyro samples. */
  public static final int GYRO = 0x98;

  /** SERAUXpac: bytes from the AUX1 serial port. */
  public static final int SERAUX1 = 0xB0;

  /** SERAUX2pac: bytes from AUX2. */
  public static final int SERAUX2 = 0xB8;

  /** TCM2pac: compass module data. */
  public static final int TCM2 = 0xC0;

  /** SERAUX3pac: bytes from AUX3. */
  public static final int SERAUX3 = 0xC8;

  /** GRIPPERpac: gripper state. */
  public static final int GRIPPER = 0xE0;

  /** IOpac: digital and analog I/O. */
  public static final int IO = 0xF0;

  /** JOYSTICKpac: the robot's joystick. */
  public static final int JOYSTICK = 0xF8;

  /** Simulator laser scan. */
  public static final int SIM_LASER = 0x60;

  /** Simulator laser scan with reflectance. */
  public static final int SIM_LASER_EXTENDED = 0x61;

  /** SIMSTAT: simulator status and true pose. */
  public static final int SIMSTAT = 0x62;

  /** SIMINFO: simulator name, version and devices. */
  public static final int SIMINFO = 0x63;

  /** SIM_MAP_CHANGED: the simulator loaded a map. */
  public static final int SIM_MAP_CHANGED = 0x66;

  /** The controller is resetting: the client must drop the connection. */
  public static final int CONTROLLER_RESET = 0xFF;

  /** Also sent by a resetting controller. */
  public static final int CONTROLLER_RESET_2 = 0xFE;

  private PacketIds() {}

  /** Whether {@code id} is a standard SIP (0x32 or 0x33). */
  public static boolean isStandardSip(int id) {
    return id == SIP_STOPPED || id == SIP_MOVING;
  }
}
