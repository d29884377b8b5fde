package org.jaria.protocol.packets;

import org.jaria.protocol.ArRobotPacket;

/**
 * The standard SIP (0x32 stopped / 0x33 moving), decoded into plain fields.
 *
 * <p>This is the hottest packet: a robot sends ten per second and a simulator builds them for every
 * robot. One instance is meant to be reused: {@link #decode} fills it without allocating, {@link
 * #encode} writes it without allocating. Values are raw robot units; conversion factors are applied
 * by the caller (ArRobot), which knows the robot's parameters.
 *
 * <p>Fields after the sonar readings are optional: older firmware stops earlier. {@link
 * #getOptionalCount()} tells how many of them were present, in the order of {@link Optional}.
 *
 * <p>Not thread-safe.
 */
public final class StandardSip {

  /** The optional tail fields in wire order, with their sizes in bytes. */
  public enum Optional {
    GRIP_STATE(1),
    ANPORT(1),
    ANALOG(1),
    DIGIN(1),
    DIGOUT(1),
    BATTERY_X10(2),
    CHARGE_STATE(1),
    ROT_VEL(2),
    FAULT_FLAGS(2),
    LAT_VEL(2),
    TEMPERATURE(1),
    SOC(1),
    UC_TIME(4),
    FLAGS3(4);

    private final int size;

    Optional(int size) {
      this.size = size;
    }

    /** Size on the wire, bytes. */
    public int size() {
      return size;
    }
  }

  /** Most sonar readings one SIP can hold (its payload is at most 200 bytes). */
  public static final int MAX_SONAR_READINGS = 64;

  private int id = PacketIds.SIP_STOPPED;
  private int xPos;
  private int yPos;
  private int thPos;
  private int leftVel;
  private int rightVel;
  private int battery;
  private int stallAndBumpers;
  private int control;
  private int flags;
  private int compass;
  private int sonarCount;
  private final int[] sonarNumbers = new int[MAX_SONAR_READINGS];
  private final int[] sonarRanges = new int[MAX_SONAR_READINGS];
  private int optionalCount;
  private int gripState;
  private int anPort;
  private int analog;
  private int digIn;
  private int digOut;
  private int batteryX10;
  private int chargeState;
  private int rotVel;
  private int faultFlags;
  private int latVel;
  private int temperature;
  private int soc;
  private long ucTime;
  private long flags3;

  /**
   * Fills this SIP from {@code p}. Returns {@code false}, leaving this object in an unspecified
   * state, if {@code p} is not a standard SIP or is too short for its mandatory fields and the
   * sonar readings it announces.
   */
  public boolean decode(ArRobotPacket p) {
    if (!PacketIds.isStandardSip(p.getID())) {
      return false;
    }
    p.resetRead();
    id = p.getID();
    xPos = p.bufToUByte2() & 0x7FFF;
    yPos = p.bufToUByte2() & 0x7FFF;
    thPos = p.bufToByte2();
    leftVel = p.bufToByte2();
    rightVel = p.bufToByte2();
    battery = p.bufToUByte();
    stallAndBumpers = p.bufToUByte2();
    control = p.bufToByte2();
    flags = p.bufToUByte2();
    compass = p.bufToUByte();
    sonarCount = p.bufToUByte();
    if (!p.isValid() || sonarCount > MAX_SONAR_READINGS || !p.isNextGood(sonarCount * 3)) {
      return false;
    }
    for (int i = 0; i < sonarCount; i++) {
      sonarNumbers[i] = p.bufToUByte();
      sonarRanges[i] = p.bufToUByte2();
    }
    optionalCount = 0;
    for (Optional o : OPTIONALS) {
      if (!p.isNextGood(o.size)) {
        break;
      }
      readOptional(p, o);
      optionalCount++;
    }
    return true;
  }

  private static final Optional[] OPTIONALS = Optional.values();

  private void readOptional(ArRobotPacket p, Optional o) {
    switch (o) {
      case GRIP_STATE -> gripState = p.bufToUByte();
      case ANPORT -> anPort = p.bufToUByte();
      case ANALOG -> analog = p.bufToUByte();
      case DIGIN -> digIn = p.bufToUByte();
      case DIGOUT -> digOut = p.bufToUByte();
      case BATTERY_X10 -> batteryX10 = p.bufToUByte2();
      case CHARGE_STATE -> chargeState = p.bufToByte();
      case ROT_VEL -> rotVel = p.bufToByte2();
      case FAULT_FLAGS -> faultFlags = p.bufToUByte2();
      case LAT_VEL -> latVel = p.bufToByte2();
      case TEMPERATURE -> temperature = p.bufToByte();
      case SOC -> soc = p.bufToByte();
      case UC_TIME -> ucTime = p.bufToUByte4();
      case FLAGS3 -> flags3 = p.bufToUByte4();
    }
  }

  private void writeOptional(ArRobotPacket p, Optional o) {
    switch (o) {
      case GRIP_STATE -> p.uByteToBuf(gripState);
      case ANPORT -> p.uByteToBuf(anPort);
      case ANALOG -> p.uByteToBuf(analog);
      case DIGIN -> p.uByteToBuf(digIn);
      case DIGOUT -> p.uByteToBuf(digOut);
      case BATTERY_X10 -> p.uByte2ToBuf(batteryX10);
      case CHARGE_STATE -> p.byteToBuf(chargeState);
      case ROT_VEL -> p.byte2ToBuf(rotVel);
      case FAULT_FLAGS -> p.uByte2ToBuf(faultFlags);
      case LAT_VEL -> p.byte2ToBuf(latVel);
      case TEMPERATURE -> p.byteToBuf(temperature);
      case SOC -> p.byteToBuf(soc);
      case UC_TIME -> p.uByte4ToBuf(ucTime);
      case FLAGS3 -> p.uByte4ToBuf(flags3);
    }
  }

  /** Writes this SIP into {@code p} (emptied first) and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(id);
    p.uByte2ToBuf(xPos & 0x7FFF).uByte2ToBuf(yPos & 0x7FFF).byte2ToBuf(thPos);
    p.byte2ToBuf(leftVel).byte2ToBuf(rightVel).uByteToBuf(battery);
    p.uByte2ToBuf(stallAndBumpers).byte2ToBuf(control).uByte2ToBuf(flags).uByteToBuf(compass);
    p.uByteToBuf(sonarCount);
    for (int i = 0; i < sonarCount; i++) {
      p.uByteToBuf(sonarNumbers[i]).uByte2ToBuf(sonarRanges[i]);
    }
    for (int i = 0; i < optionalCount; i++) {
      writeOptional(p, OPTIONALS[i]);
    }
    return p.finalizePacket();
  }

  /** Removes all sonar readings. */
  public StandardSip clearSonar() {
    sonarCount = 0;
    return this;
  }

  /**
   * Adds a sonar reading (sonar number 0..31, range in sonar units).
   *
   * @throws IllegalStateException if the SIP already holds {@link #MAX_SONAR_READINGS}
   */
  public StandardSip addSonar(int number, int range) {
    if (sonarCount == MAX_SONAR_READINGS) {
      throw new IllegalStateException("a SIP holds at most " + MAX_SONAR_READINGS + " readings");
    }
    sonarNumbers[sonarCount] = number;
    sonarRanges[sonarCount] = range;
    sonarCount++;
    return this;
  }

  // ---------------------------------------------------------------- accessors

  /** 0x32 (stopped) or 0x33 (moving). */
  public int getId() {
    return id;
  }

  /** Whether the robot reported itself moving (ID 0x33). */
  public boolean isMoving() {
    return id == PacketIds.SIP_MOVING;
  }

  /** Sets moving (0x33) or stopped (0x32). */
  public StandardSip setMoving(boolean moving) {
    id = moving ? PacketIds.SIP_MOVING : PacketIds.SIP_STOPPED;
    return this;
  }

  /** X position, 15 bits, robot distance units. */
  public int getXPos() {
    return xPos;
  }

  /** Y position, 15 bits, robot distance units. */
  public int getYPos() {
    return yPos;
  }

  /** Heading in robot angle units (2π/4096 on a Pioneer). */
  public int getThPos() {
    return thPos;
  }

  /** Sets the position; x and y are reduced to 15 bits as on the wire. */
  public StandardSip setPos(int x, int y, int th) {
    xPos = x & 0x7FFF;
    yPos = y & 0x7FFF;
    thPos = (short) th;
    return this;
  }

  /** Left wheel velocity, robot velocity units. */
  public int getLeftVel() {
    return leftVel;
  }

  /** Right wheel velocity, robot velocity units. */
  public int getRightVel() {
    return rightVel;
  }

  /** Sets the wheel velocities. */
  public StandardSip setWheelVels(int left, int right) {
    leftVel = (short) left;
    rightVel = (short) right;
    return this;
  }

  /** Battery voltage, decivolts (0..255). */
  public int getBattery() {
    return battery;
  }

  /** Sets the battery voltage, decivolts. */
  public StandardSip setBattery(int decivolts) {
    battery = decivolts & 0xFF;
    return this;
  }

  /** Stall bits (0 left, 8 right) and bumper bits (1..7, 9..15). */
  public int getStallAndBumpers() {
    return stallAndBumpers;
  }

  /** Sets the stall and bumper bits. */
  public StandardSip setStallAndBumpers(int bits) {
    stallAndBumpers = bits & 0xFFFF;
    return this;
  }

  /** Heading setpoint, degrees. */
  public int getControl() {
    return control;
  }

  /** Sets the heading setpoint. */
  public StandardSip setControl(int degrees) {
    control = (short) degrees;
    return this;
  }

  /** Flags: bit 0 motors enabled, 1..4 sonar arrays, 5 e-stop, ... */
  public int getFlags() {
    return flags;
  }

  /** Sets the flags word. */
  public StandardSip setFlags(int f) {
    flags = f & 0xFFFF;
    return this;
  }

  /** Compass heading, 2° per unit (0 if no compass). */
  public int getCompass() {
    return compass;
  }

  /** Sets the compass byte. */
  public StandardSip setCompass(int c) {
    compass = c & 0xFF;
    return this;
  }

  /** How many sonar readings this SIP carries. */
  public int getSonarCount() {
    return sonarCount;
  }

  /** The sonar number (0..31) of reading {@code i}. */
  public int getSonarNumber(int i) {
    return sonarNumbers[i];
  }

  /** The range of reading {@code i}, sonar units. */
  public int getSonarRange(int i) {
    return sonarRanges[i];
  }

  /** How many optional tail fields are present, in {@link Optional} order. */
  public int getOptionalCount() {
    return optionalCount;
  }

  /** Whether optional field {@code o} is present. */
  public boolean has(Optional o) {
    return o.ordinal() < optionalCount;
  }

  /** Sets how many optional tail fields {@link #encode} writes. */
  public StandardSip setOptionalCount(int n) {
    if (n < 0 || n > OPTIONALS.length) {
      throw new IllegalArgumentException("optional count " + n + " not in 0.." + OPTIONALS.length);
    }
    optionalCount = n;
    return this;
  }

  /** Gripper state bits. */
  public int getGripState() {
    return gripState;
  }

  /** Selected analog port. */
  public int getAnPort() {
    return anPort;
  }

  /** Selected analog input, 0..255 for 0..5 V. */
  public int getAnalog() {
    return analog;
  }

  /** Digital inputs. */
  public int getDigIn() {
    return digIn;
  }

  /** Digital outputs. */
  public int getDigOut() {
    return digOut;
  }

  /** Battery voltage, decivolts (16 bits). */
  public int getBatteryX10() {
    return batteryX10;
  }

  /** Charge state: −1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float. */
  public int getChargeState() {
    return chargeState;
  }

  /** Rotational velocity, 0.1 deg/s. */
  public int getRotVel() {
    return rotVel;
  }

  /** Fault flags. */
  public int getFaultFlags() {
    return faultFlags;
  }

  /** Lateral velocity (newer firmware). */
  public int getLatVel() {
    return latVel;
  }

  /** Temperature, °C (newer firmware). */
  public int getTemperature() {
    return temperature;
  }

  /** State of charge, % (newer firmware). */
  public int getSoc() {
    return soc;
  }

  /** Microcontroller time (newer firmware). */
  public long getUcTime() {
    return ucTime;
  }

  /** Third flags word (newer firmware). */
  public long getFlags3() {
    return flags3;
  }

  /** Sets the I/O part of the tail. */
  public StandardSip setIo(int gripState, int anPort, int analog, int digIn, int digOut) {
    this.gripState = gripState & 0xFF;
    this.anPort = anPort & 0xFF;
    this.analog = analog & 0xFF;
    this.digIn = digIn & 0xFF;
    this.digOut = digOut & 0xFF;
    return this;
  }

  /** Sets battery, charge state, rotational velocity and fault flags of the tail. */
  public StandardSip setPower(int batteryX10, int chargeState, int rotVel, int faultFlags) {
    this.batteryX10 = batteryX10 & 0xFFFF;
    this.chargeState = (byte) chargeState;
    this.rotVel = (short) rotVel;
    this.faultFlags = faultFlags & 0xFFFF;
    return this;
  }

  /** Sets the newer-firmware part of the tail. */
  public StandardSip setExtended(int latVel, int temperature, int soc, long ucTime, long flags3) {
    this.latVel = (short) latVel;
    this.temperature = (byte) temperature;
    this.soc = (byte) soc;
    this.ucTime = ucTime & 0xFFFFFFFFL;
    this.flags3 = flags3 & 0xFFFFFFFFL;
    return this;
  }
}
