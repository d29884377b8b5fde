package org.jaria.protocol.packets;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.Map;
import java.util.Objects;
import org.jaria.protocol.ArRobotPacket;

/**
 * CONFIGpac (0x20): the robot's FLASH configuration, sent in answer to the CONFIG command (ARIA's
 * {@code ArRobotConfigPacketReader}).
 *
 * <p>The packet has some sixty fields; they are described once, in wire order, by {@link Field},
 * and both {@link #decode} and {@link #encode} walk that table, so the two directions cannot
 * disagree. The order is the one ARIA's {@code ArRobotConfigPacketReader} reads (ARIA 2.9.1 and
 * AriaCoda alike) and MobileSim sends: after ShutdownVolts one firmware version string, then the
 * gyro calibration, the kinematics delay, the lateral limits and the charge threshold. Fields from
 * {@link Field#FIRMWARE_VERSION} on are absent in older firmware; bytes after the last known field
 * (newer firmware: PDB port, gyro rate limit, power bits, ...) are kept and written back unchanged.
 */
public final class ArConfigPacket {

  /** Wire types of the fields. */
  enum Kind {
    STR,
    U8,
    I8,
    U16,
    I16
  }

  /** The fields of CONFIGpac in wire order. */
  public enum Field {
    TYPE(Kind.STR),
    SUBTYPE(Kind.STR),
    SERIAL_NUMBER(Kind.STR),
    LEGACY(Kind.U8),
    ROT_VEL_TOP(Kind.U16),
    TRANS_VEL_TOP(Kind.U16),
    ROT_ACCEL_TOP(Kind.U16),
    TRANS_ACCEL_TOP(Kind.U16),
    PWM_MAX(Kind.U16),
    NAME(Kind.STR),
    SIP_CYCLE_TIME(Kind.U8),
    HOST_BAUD(Kind.U8),
    AUX1_BAUD(Kind.U8),
    HAS_GRIPPER(Kind.U16),
    FRONT_SONAR(Kind.U16),
    REAR_SONAR(Kind.U8),
    LOW_BATTERY(Kind.U16),
    REV_COUNT(Kind.U16),
    WATCHDOG(Kind.U16),
    NORMAL_MPACS(Kind.U8),
    STALL_VAL(Kind.U16),
    STALL_COUNT(Kind.U16),
    JOY_VEL(Kind.U16),
    JOY_ROT_VEL(Kind.U16),
    ROT_VEL_MAX(Kind.U16),
    TRANS_VEL_MAX(Kind.U16),
    ROT_ACCEL(Kind.U16),
    ROT_DECEL(Kind.U16),
    ROT_KP(Kind.U16),
    ROT_KV(Kind.U16),
    ROT_KI(Kind.U16),
    TRANS_ACCEL(Kind.U16),
    TRANS_DECEL(Kind.U16),
    TRANS_KP(Kind.U16),
    TRANS_KV(Kind.U16),
    TRANS_KI(Kind.U16),
    FRONT_BUMPS(Kind.U8),
    REAR_BUMPS(Kind.U8),
    HAS_CHARGER(Kind.U8),
    SONAR_CYCLE(Kind.U8),
    RESET_BAUD(Kind.U8),
    HAS_GYRO(Kind.U8),
    DRIFT_FACTOR(Kind.I16),
    AUX2_BAUD(Kind.U8),
    AUX3_BAUD(Kind.U8),
    TICKS_MM(Kind.U16),
    SHUTDOWN_VOLTS(Kind.U16),
    /** The firmware version as one string, e.g. "5.2" (MobileSim: "S.0"). */
    FIRMWARE_VERSION(Kind.STR),
    GYRO_CW(Kind.U16),
    GYRO_CCW(Kind.U16),
    KINEMATICS_DELAY(Kind.U8),
    LAT_VEL_TOP(Kind.U16),
    LAT_ACCEL_TOP(Kind.U16),
    LAT_VEL_MAX(Kind.U16),
    LAT_ACCEL(Kind.U16),
    LAT_DECEL(Kind.U16),
    CHARGE_THRESHOLD(Kind.U16);

    final Kind kind;

    Field(Kind kind) {
      this.kind = kind;
    }

    /** Whether the field is a string. */
    public boolean isString() {
      return kind == Kind.STR;
    }
  }

  private static final Field[] FIELDS = Field.values();

  /** Fields before this one are always present. */
  public static final Field FIRST_OPTIONAL = Field.FIRMWARE_VERSION;

  private final Map<Field, String> strings = new EnumMap<>(Field.class);
  private final int[] ints = new int[FIELDS.length];
  private int presentCount = FIELDS.length;
  private byte[] extra = new byte[0];

  /** An all-zero packet with every field present. */
  public ArConfigPacket() {
    for (Field f : FIELDS) {
      if (f.isString()) {
        strings.put(f, "");
      }
    }
  }

  /**
   * Decodes {@code p}. Returns {@code null} if it is not a CONFIGpac or ends before the fields
   * every firmware sends.
   */
  public static ArConfigPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.CONFIG) {
      return null;
    }
    p.resetRead();
    ArConfigPacket c = new ArConfigPacket();
    int n = 0;
    for (Field f : FIELDS) {
      if (f.ordinal() >= FIRST_OPTIONAL.ordinal() && p.remaining() == 0) {
        break;
      }
      switch (f.kind) {
        case STR -> c.strings.put(f, p.bufToString());
        case U8 -> c.ints[f.ordinal()] = p.bufToUByte();
        case I8 -> c.ints[f.ordinal()] = p.bufToByte();
        case U16 -> c.ints[f.ordinal()] = p.bufToUByte2();
        case I16 -> c.ints[f.ordinal()] = p.bufToByte2();
      }
      if (!p.isValid()) {
        return null;
      }
      n++;
    }
    c.presentCount = n;
    c.extra = new byte[p.remaining()];
    p.bufToData(c.extra, 0, c.extra.length);
    return c;
  }

  /** Writes this configuration into {@code p} (emptied first) and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.CONFIG);
    for (int i = 0; i < presentCount; i++) {
      Field f = FIELDS[i];
      int v = ints[i];
      switch (f.kind) {
        case STR -> p.strToBuf(strings.get(f));
        case U8, I8 -> p.byteToBuf(v);
        case U16, I16 -> p.byte2ToBuf(v);
      }
    }
    if (presentCount == FIELDS.length) {
      p.dataToBuf(extra, 0, extra.length);
    }
    return p.finalizePacket();
  }

  /** The value of an integer field (0 if absent). */
  public int getInt(Field f) {
    if (f.isString()) {
      throw new IllegalArgumentException(f + " is a string field; use getString");
    }
    return ints[f.ordinal()];
  }

  /** The value of a string field ("" if absent). */
  public String getString(Field f) {
    if (!f.isString()) {
      throw new IllegalArgumentException(f + " is an integer field; use getInt");
    }
    return strings.get(f);
  }

  /** Sets an integer field. */
  public ArConfigPacket set(Field f, int value) {
    if (f.isString()) {
      throw new IllegalArgumentException(f + " is a string field");
    }
    ints[f.ordinal()] = value;
    return this;
  }

  /** Sets a string field. */
  public ArConfigPacket set(Field f, String value) {
    if (!f.isString()) {
      throw new IllegalArgumentException(f + " is an integer field");
    }
    strings.put(f, Objects.requireNonNull(value));
    return this;
  }

  /** Whether field {@code f} was in the packet (older firmware omits the later ones). */
  public boolean has(Field f) {
    return f.ordinal() < presentCount;
  }

  /** Bytes after the last known field, kept as they came. */
  public byte[] getExtra() {
    return extra.clone();
  }

  /** Sets the bytes written after the last known field. */
  public ArConfigPacket setExtra(byte[] bytes) {
    extra = bytes.clone();
    return this;
  }

  // ARIA's names for the fields users read most.

  /** Robot type, e.g. "Pioneer". */
  public String getType() {
    return getString(Field.TYPE);
  }

  /** Robot subtype, e.g. "p3dx-sh". */
  public String getSubType() {
    return getString(Field.SUBTYPE);
  }

  /** Serial number ("SIM" on a simulator). */
  public String getSerialNumber() {
    return getString(Field.SERIAL_NUMBER);
  }

  /** Robot name. */
  public String getName() {
    return getString(Field.NAME);
  }

  /** Firmware version, e.g. "5.2". */
  public String getFirmwareVersion() {
    return getString(Field.FIRMWARE_VERSION);
  }

  /** Top rotational velocity the FLASH allows, deg/s. */
  public int getRotVelTop() {
    return getInt(Field.ROT_VEL_TOP);
  }

  /** Top translational velocity the FLASH allows, mm/s. */
  public int getTransVelTop() {
    return getInt(Field.TRANS_VEL_TOP);
  }

  /** Default maximum translational velocity, mm/s. */
  public int getTransVelMax() {
    return getInt(Field.TRANS_VEL_MAX);
  }

  /** Default maximum rotational velocity, deg/s. */
  public int getRotVelMax() {
    return getInt(Field.ROT_VEL_MAX);
  }

  /** SIP cycle, ms. */
  public int getSipCycleTime() {
    return getInt(Field.SIP_CYCLE_TIME);
  }

  /** Watchdog time, ms. */
  public int getWatchdog() {
    return getInt(Field.WATCHDOG);
  }

  /** Whether the robot has a gyro (0 none, 1 client-side, 2 server-side). */
  public int getHasGyro() {
    return getInt(Field.HAS_GYRO);
  }

  /** Encoder ticks per mm. */
  public int getTicksMM() {
    return getInt(Field.TICKS_MM);
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof ArConfigPacket c
        && c.presentCount == presentCount
        && Arrays.equals(c.ints, ints)
        && c.strings.equals(strings)
        && Arrays.equals(c.extra, extra);
  }

  @Override
  public int hashCode() {
    return Objects.hash(presentCount, Arrays.hashCode(ints), strings, Arrays.hashCode(extra));
  }

  @Override
  public String toString() {
    StringBuilder sb = new StringBuilder("ArConfigPacket[");
    for (int i = 0; i < presentCount; i++) {
      Field f = FIELDS[i];
      if (i > 0) {
        sb.append(", ");
      }
      sb.append(f).append('=').append(f.isString() ? strings.get(f) : ints[i]);
    }
    return sb.append(']').toString();
  }
}
